#pragma once
// The one finite-difference Jacobian checker of the test suites: every analytic Jacobian (the SLAM
// models, the NDT scores' gradients and Hessians, the pose-graph factor) is held against central
// differences here, one line per check:
//
//   expect_jacobian_near(model.process_jacobian(x, u), central_jacobian(process_of_x, x), 1e-6, "F_x");
#include <functional>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Core>

namespace sextant::test {

/// J(:, i) = (f(x + h·eᵢ) − f(x − h·eᵢ)) / 2h. `wrap` (optional) is applied to each difference
/// before dividing, e.g. to wrap angle outputs into (−π, π].
inline Eigen::MatrixXd central_jacobian(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& f,
                                        const Eigen::VectorXd& x, double h = 1e-6,
                                        const std::function<void(Eigen::VectorXd&)>& wrap = {}) {
  const Eigen::VectorXd f0 = f(x);
  Eigen::MatrixXd J(f0.size(), x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    Eigen::VectorXd plus = x, minus = x;
    plus[i] += h;
    minus[i] -= h;
    Eigen::VectorXd d = f(plus) - f(minus);
    if (wrap) wrap(d);
    J.col(i) = d / (2 * h);
  }
  return J;
}

/// Every element |analytic − numeric| ≤ tolerance · (1 + |numeric|); the failure prints both.
inline void expect_jacobian_near(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& numeric,
                                 double tolerance, const std::string& what) {
  ASSERT_EQ(analytic.rows(), numeric.rows()) << what;
  ASSERT_EQ(analytic.cols(), numeric.cols()) << what;
  const Eigen::MatrixXd bound =
      tolerance * (Eigen::MatrixXd::Ones(numeric.rows(), numeric.cols()) + numeric.cwiseAbs());
  EXPECT_TRUE(((analytic - numeric).cwiseAbs().array() <= bound.array()).all()) << what << "\nanalytic\n"
                                                                                << analytic << "\nnumeric\n"
                                                                                << numeric;
}

}  // namespace sextant::test
