// Analytic gradient and Hessian of both scores against central finite differences.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "ndt/ndt_score.hpp"
#include "sextant_test/finite_differences.hpp"
#include "test_clouds.hpp"

namespace sextant {
namespace {

struct Fixture {
  NdtGrid grid;
  PointCloud input;
};

Fixture make_fixture() {
  Rng rng(11);
  const PointCloud reference = test::yard(rng);
  Fixture f;
  f.grid = NdtGrid::build_over_bounds(reference, 3.0);
  Rng rng2(12);
  const PointCloud scan = test::yard(rng2);
  for (std::size_t i = 0; i < scan.size(); i += 20) f.input.push_back(scan[i]);
  return f;
}

template <class Score>
void check_derivatives(const Score& score, const Vector6d& xi) {
  const ScoreEvaluation at = score(xi, Derivatives::kHessian);
  ASSERT_GT(at.matched, 100u);
  const auto evaluate = [&](const Eigen::VectorXd& x) {
    const ScoreEvaluation e = score(Vector6d(x), Derivatives::kHessian);
    EXPECT_EQ(e.matched, at.matched) << "a point changed cell; choose another pose";
    return e;
  };
  const auto value = [&](const Eigen::VectorXd& x) {
    return Eigen::VectorXd::Constant(1, evaluate(x).score);
  };
  const auto gradient = [&](const Eigen::VectorXd& x) { return Eigen::VectorXd(evaluate(x).gradient); };
  test::expect_jacobian_near(at.gradient.transpose(), test::central_jacobian(value, xi), 1e-5, "gradient");
  test::expect_jacobian_near(at.hessian, test::central_jacobian(gradient, xi), 1e-4, "hessian");
  EXPECT_LT((at.hessian - at.hessian.transpose()).norm(), 1e-9 * at.hessian.norm());
}

TEST(NdtScore, MahalanobisDerivativesMatchFiniteDifferences) {
  const Fixture f = make_fixture();
  Vector6d xi;
  xi << 0.31, -0.22, 0.05, 0.03, -0.02, 0.12;
  check_derivatives(
      [&](const Vector6d& x, Derivatives d) { return mahalanobis_score(f.grid, f.input, x, d); }, xi);
}

TEST(NdtScore, MahalanobisGaussNewtonIsFirstHessianTerm) {
  const Fixture f = make_fixture();
  // At ξ where every e = 0 the second-order term vanishes; in general GN is PSD.
  Vector6d xi;
  xi << 0.1, 0.1, 0.0, 0.01, 0.02, -0.05;
  const ScoreEvaluation e = mahalanobis_score(f.grid, f.input, xi, Derivatives::kHessian);
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Matrix6d>(e.gauss_newton).eigenvalues().minCoeff(), 0.0);
}

TEST(NdtScore, GaussianDerivativesMatchFiniteDifferences) {
  const Fixture f = make_fixture();
  const GaussianScoreParams p = GaussianScoreParams::from_outlier_ratio(0.55, 3.0);
  EXPECT_LT(p.d1, 0.0);
  EXPECT_GT(p.d2, 0.0);
  Vector6d xi;
  xi << -0.2, 0.15, 0.02, -0.01, 0.03, 0.08;
  check_derivatives(
      [&](const Vector6d& x, Derivatives d) { return gaussian_score(f.grid, f.input, x, p, false, d); }, xi);
}

TEST(NdtScore, MagnussonConstantsMatchPclDefaults) {
  // PCL's NDT with outlier ratio 0.55 and resolution 1 m: d1 ≈ −1.4604, d2 ≈ 0.4573 (hand-computed
  // from the formulas in the header).
  const GaussianScoreParams p = GaussianScoreParams::from_outlier_ratio(0.55, 1.0);
  const double c1 = 4.5, c2 = 0.55, d3 = -std::log(c2);
  EXPECT_NEAR(p.d1, -std::log(c1 + c2) - d3, 1e-12);
  EXPECT_NEAR(p.d2, -2.0 * std::log((-std::log(c1 * std::exp(-0.5) + c2) - d3) / p.d1), 1e-12);
}

TEST(NdtScore, NonFinitePoseScoresNothing) {
  const Fixture f = make_fixture();
  Vector6d xi = Vector6d::Zero();
  xi(4) = std::nan("");
  const ScoreEvaluation e = mahalanobis_score(f.grid, f.input, xi, Derivatives::kHessian);
  EXPECT_EQ(e.matched, 0u);
  EXPECT_TRUE(e.hessian.allFinite());
}

}  // namespace
}  // namespace sextant
