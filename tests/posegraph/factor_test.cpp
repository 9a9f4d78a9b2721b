// The relative-pose factor: its residual on known cases, its automatic Jacobians against central
// finite differences, and the information it takes from a registration Hessian (eq. 3.50).
#include <ceres/cost_function.h>

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "sextant/core/rng.hpp"
#include "sextant/posegraph/relative_pose_factor.hpp"
#include "sextant_test/finite_differences.hpp"

namespace sextant {
namespace {

Eigen::Isometry3d random_pose(Rng& rng, double spread) {
  return to_isometry({rng.uniform(-spread, spread), rng.uniform(-spread, spread), rng.uniform(-1, 1),
                      rng.uniform(-0.4, 0.4), rng.uniform(-0.4, 0.4), rng.uniform(-3.1, 3.1)});
}

TEST(RelativePoseFactor, ErrorIsZeroWhenConsistentAndTheLogMapOtherwise) {
  Rng rng(3);
  const Eigen::Isometry3d a = random_pose(rng, 20), b = random_pose(rng, 20);
  EXPECT_LT(relative_pose_error(relative(a, b), a, b).norm(), 1e-12);
  // E = R_z(0.3) with a 1 m step along x: e = (1, 0, 0, 0, 0, 0.3).
  const Eigen::Isometry3d step = to_isometry({1, 0, 0, 0, 0, 0.3});
  const Vector6d e = relative_pose_error(Eigen::Isometry3d::Identity(), Eigen::Isometry3d::Identity(), step);
  EXPECT_NEAR((e - (Vector6d() << 1, 0, 0, 0, 0, 0.3).finished()).norm(), 0.0, 1e-12);
  // The rotation vector of a 170° turn keeps its full angle (log map, not the small-angle 2·vec(q)).
  const Vector6d big = relative_pose_error(Eigen::Isometry3d::Identity(), Eigen::Isometry3d::Identity(),
                                           to_isometry({0, 0, 0, 2.967, 0, 0}));
  EXPECT_NEAR(big[3], 2.967, 1e-9);
}

TEST(RelativePoseFactor, AutomaticJacobiansMatchCentralDifferences) {
  Rng rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Isometry3d Ti = random_pose(rng, 30), Tj = random_pose(rng, 30);
    // A measurement near the graph's relative pose (a realistic edge) or far from it (a false one).
    const Eigen::Isometry3d noise = random_pose(rng, trial % 2 ? 0.2 : 5.0);
    const Eigen::Isometry3d measured = relative(Ti, Tj) * noise;
    Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Random();
    const Matrix6d omega = A * A.transpose() + Matrix6d::Identity();
    Matrix6d L;
    ASSERT_TRUE(sqrt_information(omega, &L));
    const std::unique_ptr<ceres::CostFunction> cost(make_relative_pose_cost(measured, L));

    Eigen::VectorXd x(14);  // t_i q_i t_j q_j (q in Eigen's x y z w)
    const Eigen::Quaterniond qi(Ti.rotation()), qj(Tj.rotation());
    x << Ti.translation(), qi.coeffs(), Tj.translation(), qj.coeffs();
    const int sizes[4] = {3, 4, 3, 4}, offsets[4] = {0, 3, 7, 10};
    const auto residual = [&](const Eigen::VectorXd& p, double** jacobians) {
      const double* blocks[4] = {&p[0], &p[3], &p[7], &p[10]};
      Eigen::VectorXd r(6);
      EXPECT_TRUE(cost->Evaluate(blocks, r.data(), jacobians));
      return r;
    };
    // Ceres' row-major blocks of 6 × size, side by side: the analytic 6 × 14 Jacobian.
    std::vector<Eigen::Matrix<double, 6, Eigen::Dynamic, Eigen::RowMajor>> J(4);
    double* jac[4];
    for (int b = 0; b < 4; ++b) {
      J[b].resize(6, sizes[b]);
      jac[b] = J[b].data();
    }
    residual(x, jac);
    Eigen::MatrixXd analytic(6, 14);
    for (int b = 0; b < 4; ++b) analytic.middleCols(offsets[b], sizes[b]) = J[b];
    test::expect_jacobian_near(
        analytic, test::central_jacobian([&](const Eigen::VectorXd& p) { return residual(p, nullptr); }, x),
        1e-5, "trial " + std::to_string(trial));
  }
}

TEST(RelativePoseFactor, SqrtInformationRefusesSingularAndNonFinite) {
  Matrix6d L;
  ASSERT_TRUE(sqrt_information(4.0 * Matrix6d::Identity(), &L));
  EXPECT_NEAR((L - 2.0 * Matrix6d::Identity()).norm(), 0.0, 1e-12);
  Matrix6d singular = Matrix6d::Identity();
  singular(5, 5) = 0.0;
  EXPECT_FALSE(sqrt_information(singular, &L));
  Matrix6d nan = Matrix6d::Identity();
  nan(0, 0) = std::nan("");
  EXPECT_FALSE(sqrt_information(nan, &L));
}

TEST(RelativePoseFactor, InformationFromAPose6HessianRotatesWithTheMeasurement) {
  // At the identity the error is the Pose6 vector to first order: Ω = H.
  Matrix6d H = Matrix6d::Zero();
  H.diagonal() << 1, 4, 9, 16, 25, 36;
  EXPECT_NEAR((information_from_pose6_hessian(H, Eigen::Isometry3d::Identity()) - H).norm(), 0.0, 1e-6);
  // Yawed by 90°: t(E) = R_mᵀ·(t − t_m), so the translation block is R_mᵀ·H_tt·R_m (x and y swap).
  const Eigen::Isometry3d m = to_isometry({5, -2, 0.5, 0, 0, M_PI / 2});
  const Matrix6d omega = information_from_pose6_hessian(H, m);
  const Eigen::Matrix3d R = m.linear();
  const Eigen::Matrix3d expected = R.transpose() * H.topLeftCorner<3, 3>() * R;
  EXPECT_NEAR((omega.topLeftCorner<3, 3>() - expected).norm(), 0.0, 1e-5);
  EXPECT_NEAR(omega(0, 0), 4.0, 1e-5);
  EXPECT_NEAR(omega(1, 1), 1.0, 1e-5);
  // Pure yaw about z: the yaw information is unchanged.
  EXPECT_NEAR(omega(5, 5), 36.0, 1e-4);
}

}  // namespace
}  // namespace sextant
