#pragma once
// The one finite-difference Jacobian checker of the test suites: every analytic Jacobian (the SLAM
// models, the NDT scores' gradients and Hessians, the pose-graph factor, the Ackermann EKF's
// measurement) is held against central differences here, one line per check (as manif's
// MANIF_TEST_JACOBIANS):
//
//   expect_jacobian_near(model.process_jacobian(x, u), central_jacobian(process_of_x, x), 1e-6, "F_x");
//
// central_jacobian differentiates f: Rⁿ → Rᵐ on Eigen vectors, or f: M → Rᵐ on a manifold M
// (SE(3), Pose6, …) through a `plus(x, δ)` that moves x by δ ∈ Rⁿ (se3_plus for Eigen::Isometry3d).
// A failure names the worst entry (row, column, both values, the bound) and prints both matrices.
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sextant::test {

/// J(:, i) = (f(plus(x, h·eᵢ)) − f(plus(x, −h·eᵢ))) / 2h for i < dim. `wrap` (optional) is applied
/// to each difference before dividing, e.g. to wrap angle outputs into (−π, π].
template <class X, class F, class Plus>
Eigen::MatrixXd central_jacobian(const F& f, const X& x, const Plus& plus, Eigen::Index dim, double h = 1e-6,
                                 const std::function<void(Eigen::VectorXd&)>& wrap = {}) {
  Eigen::MatrixXd J;
  for (Eigen::Index i = 0; i < dim; ++i) {
    Eigen::VectorXd delta = Eigen::VectorXd::Zero(dim);
    delta[i] = h;
    Eigen::VectorXd d =
        Eigen::VectorXd(f(plus(x, delta))) - Eigen::VectorXd(f(plus(x, Eigen::VectorXd(-delta))));
    if (wrap) wrap(d);
    if (i == 0) J.resize(d.size(), dim);
    J.col(i) = d / (2 * h);
  }
  return J;
}

/// The same on Rⁿ: plus(x, δ) = x + δ.
inline Eigen::MatrixXd central_jacobian(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& f,
                                        const Eigen::VectorXd& x, double h = 1e-6,
                                        const std::function<void(Eigen::VectorXd&)>& wrap = {}) {
  return central_jacobian(
      f, x, [](const Eigen::VectorXd& v, const Eigen::VectorXd& d) { return Eigen::VectorXd(v + d); },
      x.size(), h, wrap);
}

/// The right perturbation of a rigid transform, T · (t = δ₀₋₂, R = exp([δ₃₋₅]×)): the SE(3)
/// tangent at T with translation and rotation-vector coordinates (first order equal to T·Exp(δ)).
inline Eigen::Isometry3d se3_plus(const Eigen::Isometry3d& T, const Eigen::VectorXd& delta) {
  Eigen::Isometry3d D = Eigen::Isometry3d::Identity();
  D.translation() = delta.head<3>();
  const double angle = delta.tail<3>().norm();
  if (angle > 0.0) D.linear() = Eigen::AngleAxisd(angle, delta.tail<3>() / angle).toRotationMatrix();
  return T * D;
}

/// How the tolerance scales: relative bounds |a − n| by tolerance · (1 + |n|) per entry, absolute
/// by tolerance alone.
enum class Bound { relative, absolute };

/// Success when every entry of analytic and numeric lies within the bound; otherwise the message
/// names the worst entry (largest ratio of difference to bound) and prints both matrices.
inline ::testing::AssertionResult jacobian_near(const Eigen::MatrixXd& analytic,
                                                const Eigen::MatrixXd& numeric, double tolerance,
                                                Bound bound = Bound::relative) {
  if (analytic.rows() != numeric.rows() || analytic.cols() != numeric.cols())
    return ::testing::AssertionFailure() << "analytic is " << analytic.rows() << "×" << analytic.cols()
                                         << ", numeric " << numeric.rows() << "×" << numeric.cols();
  Eigen::Index worst_r = 0, worst_c = 0;
  double worst = -1.0;
  bool ok = true;
  for (Eigen::Index c = 0; c < numeric.cols(); ++c) {
    for (Eigen::Index r = 0; r < numeric.rows(); ++r) {
      const double limit = tolerance * (bound == Bound::relative ? 1.0 + std::abs(numeric(r, c)) : 1.0);
      const double diff = std::abs(analytic(r, c) - numeric(r, c));
      const double ratio = std::isnan(diff) ? std::numeric_limits<double>::infinity() : diff / limit;
      if (!(diff <= limit)) ok = false;  // NaN fails too
      if (ratio > worst) {
        worst = ratio;
        worst_r = r;
        worst_c = c;
      }
    }
  }
  if (ok) return ::testing::AssertionSuccess();
  const double n = numeric(worst_r, worst_c), a = analytic(worst_r, worst_c);
  std::ostringstream out;
  out.precision(10);
  out << "worst entry (" << worst_r << ", " << worst_c << "): analytic " << a << ", numeric " << n
      << ", |difference| " << std::abs(a - n) << " > "
      << (bound == Bound::relative ? "tolerance·(1 + |numeric|) = " : "tolerance = ")
      << tolerance * (bound == Bound::relative ? 1.0 + std::abs(n) : 1.0) << "\nanalytic\n"
      << analytic << "\nnumeric\n"
      << numeric;
  return ::testing::AssertionFailure() << out.str();
}

/// One line per check: EXPECT_TRUE(jacobian_near(...)) << what.
inline void expect_jacobian_near(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& numeric,
                                 double tolerance, const std::string& what, Bound bound = Bound::relative) {
  EXPECT_TRUE(jacobian_near(analytic, numeric, tolerance, bound)) << what;
}

}  // namespace sextant::test
