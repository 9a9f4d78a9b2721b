// Sigma-point rules (sigma_points.hpp): the thesis-era unscented transform (Julier and Uhlmann's
// κ = 3 − n) against today's default (α = 1, β = 2, κ = 0) and the cubature rule, and the words
// every report prints for a filter's sigma-point parameters (issue 25).
#include <memory>

#include <gtest/gtest.h>

#include "sextant/filters/filter.hpp"
#include "sextant/filters/range_bearing_model.hpp"
#include "sextant/filters/sigma_points.hpp"
#include "sextant/filters/yaml.hpp"

namespace sextant {
namespace {

UnscentedSettings julier() {
  UnscentedSettings s;
  s.alpha = 1.0;
  s.beta = 0.0;
  s.kappa_three_minus_n = true;
  return s;
}

// Table 4.2 with κ = 3 − n: n + λ = 3, so the points sit at ±√3·eᵢ whatever n, the outer weights
// are 1/6 and the centre takes W₀ = (3 − n)/3 (eq. 4.84's κ/(n + κ)), negative beyond n = 3.
TEST(SigmaPoints, JuliersKappaPutsThePointsAtRootThreeWithANegativeCentreWeight) {
  Rng rng(1);
  for (const int n : {2, 3, 10, 120}) {
    const SigmaPoints sp = make_unscented_rule(julier())->generate(n, rng);
    ASSERT_EQ(sp.xi.cols(), 2 * n + 1);
    EXPECT_NEAR(sp.xi(0, 1), std::sqrt(3.0), 1e-12) << n;
    EXPECT_NEAR(sp.xi(n - 1, 2 * n), -std::sqrt(3.0), 1e-12) << n;
    EXPECT_NEAR(sp.wm[0], (3.0 - n) / 3.0, 1e-12) << n;
    EXPECT_NEAR(sp.wm[1], 1.0 / 6.0, 1e-12) << n;
    EXPECT_NEAR(sp.wm.sum(), 1.0, 1e-12) << n;
    EXPECT_TRUE(sp.wc.isApprox(sp.wm)) << "β = 0, α = 1: one set of weights";
    // First and second moments of N(0, I) are matched exactly.
    EXPECT_LT((sp.xi * sp.wm).norm(), 1e-12) << n;
    const Eigen::MatrixXd second = sp.xi * sp.wc.asDiagonal() * sp.xi.transpose();
    EXPECT_TRUE(second.isApprox(Eigen::MatrixXd::Identity(n, n), 1e-12)) << n;
  }
}

// Why E13's UKF-vs-CKF claims could not hold before issue 25: α = 1, κ = 0 gives λ = 0, the outer
// points ±√n·eᵢ with weights 1/(2n) — eqs. (4.69)–(4.70) — and a centre of mean weight 0.
TEST(SigmaPoints, TodaysDefaultUnscentedPointsAreTheCubaturePoints) {
  Rng rng(1);
  const int n = 7;
  const SigmaPoints ut = make_unscented_rule(UnscentedSettings{})->generate(n, rng);
  const SigmaPoints cub = make_cubature_rule()->generate(n, rng);
  EXPECT_DOUBLE_EQ(ut.wm[0], 0.0);
  EXPECT_TRUE(ut.xi.rightCols(2 * n).isApprox(cub.xi));
  EXPECT_TRUE(ut.wm.tail(2 * n).isApprox(cub.wm));
  const SigmaPoints thesis = make_unscented_rule(julier())->generate(n, rng);
  EXPECT_FALSE(thesis.xi.rightCols(2 * n).isApprox(cub.xi, 1e-3));
}

// The same holds through a filter on a nonlinear model: one range–bearing prediction with an
// uncertain heading. Today's UKF predicts the CKF's mean to rounding; the thesis-era one does not.
TEST(SigmaPoints, ThesisEraUkfPredictsADifferentMeanFromTheCkf) {
  auto model = std::make_shared<RangeBearingModel>();
  const auto predicted = [&](const std::string& name, const char* settings) {
    auto filter = make_filter(name, model, YAML::Load(settings));
    Eigen::VectorXd x0(7);
    x0 << 0.0, 0.0, 0.3, 10.0, 5.0, -4.0, 12.0;  // pose and two landmarks: n = 7 (+2 controls)
    const Eigen::Vector3d pose_sigma(1.0, 1.0, 0.6);
    Eigen::MatrixXd P0 = Eigen::MatrixXd::Identity(7, 7);
    P0.topLeftCorner(3, 3) = pose_sigma.cwiseAbs2().asDiagonal();
    EXPECT_TRUE(filter->initialize(x0, P0).ok());
    const Eigen::Vector2d u(40.0, 0.2);  // 2 m in dt = 0.05 s
    const Eigen::Matrix2d Q = Eigen::Vector2d(1.0, 0.1).asDiagonal();
    EXPECT_TRUE(filter->predict(u, Q).ok()) << name << " " << settings;
    return filter->mean();
  };
  const Eigen::VectorXd ckf = predicted("ckf", "{}");
  const Eigen::VectorXd today = predicted("ukf", "{}");
  const Eigen::VectorXd thesis = predicted("ukf", "{alpha: 1.0, beta: 0.0, kappa_three_minus_n: true}");
  EXPECT_LT((today - ckf).norm(), 1e-9);
  EXPECT_GT((thesis - ckf).head(3).norm(), 1e-3);
  std::printf("[sigma-points] predicted pose: ckf (%.4f %.4f %.4f), ukf κ = 3 − n (%.4f %.4f %.4f)\n", ckf[0],
              ckf[1], ckf[2], thesis[0], thesis[1], thesis[2]);
}

// The reports print Filter::approximation() per method.
TEST(SigmaPoints, EveryFilterNamesItsSigmaPointParameters) {
  auto model = std::make_shared<RangeBearingModel>();
  const auto text = [&](const std::string& name, const char* settings) {
    return make_filter(name, model, YAML::Load(settings))->approximation();
  };
  EXPECT_EQ(text("ukf", "{alpha: 1.0, beta: 0.0, kappa_three_minus_n: true}"),
            "unscented (Table 4.2): 2n+1 points, α = 1, β = 0, κ = 3 − n");
  EXPECT_EQ(text("ukf", "{}"), "unscented (Table 4.2): 2n+1 points, α = 1, β = 2, κ = 0");
  EXPECT_EQ(text("ukf", "{alpha: 1.0e-3}"), "unscented (Table 4.2): 2n+1 points, α = 0.001, β = 2, κ = 0");
  EXPECT_NE(text("ckf", "{}").find("cubature"), std::string::npos);
  EXPECT_NE(text("rspkf", "{iterations: 5}").find("N_max = 5"), std::string::npos);
  for (const char* name : {"ekf", "seif", "eif", "eseif"})
    EXPECT_NE(text(name, "{}").find("no sigma points"), std::string::npos) << name;
}

}  // namespace
}  // namespace sextant
