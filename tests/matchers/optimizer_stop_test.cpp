// When the shared optimiser loop (optimizer.hpp) ends a stage: LM does not try a step shorter than ε
// or one whose predicted decrease is below function_tolerance × the score, on objectives whose
// minimum and evaluation count are known.
#include <gtest/gtest.h>

#include "ndt/ndt_score.hpp"
#include "optim/optimizer.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant {
namespace {

/// One stage of f(ξ) = f₀ + (ξ − ξ*)ᵀA(ξ − ξ*), or (`flat`) of a score that stays f₀ wherever it
/// is evaluated while its derivatives are still the quadratic's (a kink the model cannot see, as at
/// an NDT cell boundary). Counts its evaluations.
class QuadraticStage : public StagedObjective {
 public:
  QuadraticStage(const Vector6d& minimum, double f0, bool flat) : minimum_(minimum), f0_(f0), flat_(flat) {
    A_ = Vector6d(4.0, 3.0, 2.0, 5.0, 6.0, 1.0).asDiagonal();
  }
  int stages() const override { return 1; }
  int stage_label(int) const override { return 1; }
  ScoreEvaluation evaluate(int, const Vector6d& xi, Derivatives) const override {
    ++evaluations_;
    const Vector6d d = xi - minimum_;
    ScoreEvaluation e;
    e.score = flat_ ? f0_ : f0_ + d.dot(A_ * d);
    e.gradient = 2.0 * A_ * d;
    e.hessian = 2.0 * A_;
    e.matched = input_.size();
    return e;
  }
  const NdtGrid* mahalanobis_grid(int) const override { return nullptr; }
  const PointCloud& input() const override { return input_; }
  double value(const Vector6d& xi) const { return f0_ + (xi - minimum_).dot(A_ * (xi - minimum_)); }
  int evaluations() const { return evaluations_; }

 private:
  Vector6d minimum_;
  double f0_;
  bool flat_;
  Matrix6d A_;
  PointCloud input_ = PointCloud(std::vector<Eigen::Vector3f>(10, Eigen::Vector3f::Zero()));
  mutable int evaluations_ = 0;
};

OptimizerSettings lm(double function_tolerance) {
  OptimizerSettings s;
  s.solver = SolverKind::kLevenbergMarquardt;
  s.function_tolerance = function_tolerance;
  return s;
}

const Vector6d kMinimum = (Vector6d() << 0.3, -0.2, 0.1, 0.02, -0.01, 0.05).finished();

TEST(OptimizerStop, LmReachesTheQuadraticsMinimumWithAndWithoutFunctionTolerance) {
  for (const double tolerance : {0.0, 1e-5}) {
    const QuadraticStage f(kMinimum, 100.0, false);
    const RegistrationResult r = optimize(f, Eigen::Isometry3d::Identity(), lm(tolerance));
    ASSERT_TRUE(r.converged) << tolerance;
    const Vector6d xi = to_pose6(r.T).vector();
    // f − f₀ is what the model can still gain from the start of the last step on; the tolerance
    // stops there, so f(ξ) − f₀ lies within (a little more than) tolerance × f(ξ).
    EXPECT_LE(f.value(xi) - 100.0, 2.0 * tolerance * f.value(xi) + 1e-8) << tolerance;
    if (tolerance == 0.0) {
      EXPECT_LT((xi - kMinimum).norm(), 1e-4);
    }
  }
}

TEST(OptimizerStop, FunctionToleranceSavesEvaluationsNearTheMinimum) {
  const QuadraticStage exact(kMinimum, 1e4, false), tolerant(kMinimum, 1e4, false);
  optimize(exact, Eigen::Isometry3d::Identity(), lm(0.0));
  optimize(tolerant, Eigen::Isometry3d::Identity(), lm(1e-5));
  EXPECT_LT(tolerant.evaluations(), exact.evaluations());
}

TEST(OptimizerStop, AStepShorterThanEpsilonIsNotTried) {
  // The score never decreases: every trial is rejected and λ grows ×10 until the step is shorter
  // than ε. Starting 10 cm from where the derivatives point, that takes a few tries, not the twelve
  // a stage allows; the registration ends converged where it started.
  QuadraticStage flat(kMinimum, 100.0, true);
  const Eigen::Isometry3d start = Eigen::Isometry3d::Identity();
  const RegistrationResult r = optimize(flat, start, lm(0.0));
  EXPECT_TRUE(r.converged);
  EXPECT_TRUE(r.T.isApprox(start, 1e-12));
  EXPECT_GE(flat.evaluations(), 3);   // the start and at least two rejected trials
  EXPECT_LT(flat.evaluations(), 13);  // before: the start and twelve trials
}

TEST(OptimizerStop, APredictedDecreaseBelowTheToleranceIsNotTried) {
  // Far from the quadratic's minimum, but the predicted decrease (at most f − f₀ ≈ 0.2) is below
  // 10⁻² × the score (10⁶): the start is the minimum as far as the tolerance goes, after one
  // evaluation.
  QuadraticStage f(kMinimum, 1e6, false);
  const RegistrationResult r = optimize(f, Eigen::Isometry3d::Identity(), lm(1e-2));
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(f.evaluations(), 1);
  EXPECT_TRUE(r.T.isApprox(Eigen::Isometry3d::Identity(), 1e-12));
}

TEST(OptimizerStop, FunctionToleranceIsReadCheckedAndOffInTheThesisPreset) {
  EXPECT_EQ(read_mlndt_settings(YAML::Load("{}"), "x").optimizer.function_tolerance, 1e-5);
  EXPECT_EQ(read_mlndt_settings(YAML::Load("{preset: thesis}"), "x").optimizer.function_tolerance, 0.0);
  EXPECT_EQ(read_mlndt_settings(YAML::Load("{function_tolerance: 1e-6}"), "x").optimizer.function_tolerance,
            1e-6);
  for (const char* bad :
       {"{function_tolerance: -1e-6}", "{function_tolerance: 1}", "{function_tolerance: .nan}"}) {
    try {
      read_mlndt_settings(YAML::Load(bad), "m.yaml");
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("function_tolerance"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace sextant
