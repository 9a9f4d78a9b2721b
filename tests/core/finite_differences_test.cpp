// The shared Jacobian checker itself (tests/common/sextant_test/finite_differences.hpp): it accepts a
// right Jacobian on Rⁿ and on SE(3), and it fails, naming the worst entry, on a wrong one.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cmath>

#include "sextant/core/pose.hpp"
#include "sextant_test/finite_differences.hpp"

namespace sextant {
namespace {

Eigen::VectorXd polar(const Eigen::VectorXd& x) {  // (r cos φ, r sin φ, r²)
  return Eigen::Vector3d(x[0] * std::cos(x[1]), x[0] * std::sin(x[1]), x[0] * x[0]);
}

Eigen::MatrixXd polar_jacobian(const Eigen::VectorXd& x) {
  Eigen::MatrixXd J(3, 2);
  J << std::cos(x[1]), -x[0] * std::sin(x[1]), std::sin(x[1]), x[0] * std::cos(x[1]), 2 * x[0], 0.0;
  return J;
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d S;
  S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return S;
}

TEST(FiniteDifferences, AcceptsARightJacobianOnVectors) {
  const Eigen::Vector2d x(2.0, 0.7);
  test::expect_jacobian_near(polar_jacobian(x), test::central_jacobian(polar, x), 1e-8, "polar");
  test::expect_jacobian_near(polar_jacobian(x), test::central_jacobian(polar, x), 1e-8, "polar",
                             test::Bound::absolute);
}

TEST(FiniteDifferences, AcceptsARightJacobianOnSe3) {
  // f(T) = T·p under the right perturbation T·(δt, Exp(δθ)): ∂f/∂δ = [R, −R·[p]×].
  const Eigen::Isometry3d T = to_isometry({1.0, -2.0, 0.5, 0.3, -0.2, 1.1});
  const Eigen::Vector3d p(0.4, 2.0, -1.0);
  Eigen::MatrixXd J(3, 6);
  J << T.linear(), -T.linear() * skew(p);
  const auto moved = [&](const Eigen::Isometry3d& X) { return Eigen::VectorXd(X * p); };
  test::expect_jacobian_near(J, test::central_jacobian(moved, T, test::se3_plus, 6), 1e-8, "T·p");
}

TEST(FiniteDifferences, FailsOnAWrongEntryAndNamesIt) {
  const Eigen::Vector2d x(2.0, 0.7);
  Eigen::MatrixXd wrong = polar_jacobian(x);
  wrong(2, 0) += 1e-4;  // 4 + 1e-4 instead of 4
  EXPECT_FALSE(test::jacobian_near(wrong, test::central_jacobian(polar, x), 1e-6));
  EXPECT_NONFATAL_FAILURE(test::expect_jacobian_near(wrong, test::central_jacobian(polar, x), 1e-6, "polar"),
                          "worst entry (2, 0)");
  EXPECT_FALSE(test::jacobian_near(polar_jacobian(x).leftCols(1), test::central_jacobian(polar, x), 1e-6))
      << "a size mismatch fails";
  Eigen::MatrixXd nan = polar_jacobian(x);
  nan(0, 1) = std::nan("");
  EXPECT_FALSE(test::jacobian_near(nan, test::central_jacobian(polar, x), 1e-6)) << "NaN fails";
}

}  // namespace
}  // namespace sextant
