#pragma once
// The exact Kalman filter over the joint state [pose; landmarks] of the linear-Gaussian SLAM
// model (LinearSlamModel: x' = A x + B u, z = m − C x, m = C x + z), written densely and
// independently of the filters: the reference of linear_gaussian_test.cpp and fastslam_test.cpp.
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

#include "sextant/filters/range_bearing_model.hpp"

namespace sextant::test {

struct ExactKalman {
  Eigen::MatrixXd A, B, C;
  Eigen::VectorXd x;
  Eigen::MatrixXd P;

  void predict(const Eigen::VectorXd& u, const Eigen::MatrixXd& Q) {
    const Eigen::Index n = x.size(), p = A.rows();
    Eigen::MatrixXd F = Eigen::MatrixXd::Identity(n, n);
    F.topLeftCorner(p, p) = A;
    Eigen::MatrixXd G = Eigen::MatrixXd::Zero(n, B.cols());
    G.topRows(p) = B;
    x.head(p) = A * x.head(p) + B * u;
    P = F * P * F.transpose() + G * Q * G.transpose();
  }
  void update(const std::vector<Eigen::VectorXd>& zs, const Eigen::MatrixXd& R, const std::vector<int>& ids) {
    const Eigen::Index n = x.size(), p = A.rows(), l = C.rows(), m = l * static_cast<Eigen::Index>(zs.size());
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(m, n), Rs = Eigen::MatrixXd::Zero(m, m);
    Eigen::VectorXd z(m);
    for (std::size_t j = 0; j < zs.size(); ++j) {
      H.block(l * j, 0, l, p) = -C;
      H.block(l * j, p + l * ids[j], l, l).setIdentity();
      Rs.block(l * j, l * j, l, l) = R;
      z.segment(l * j, l) = zs[j];
    }
    const Eigen::MatrixXd S = H * P * H.transpose() + Rs;
    const Eigen::MatrixXd K = P * H.transpose() * S.inverse();
    x += K * (z - H * x);
    P = (Eigen::MatrixXd::Identity(n, n) - K * H) * P;
    P = 0.5 * (P + P.transpose());
  }
  void augment(const Eigen::VectorXd& z, const Eigen::MatrixXd& R) {
    const Eigen::Index n = x.size(), p = A.rows(), l = C.rows();
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n + l, n + l);  // [x; m] = J [x; z]
    J.topLeftCorner(n, n).setIdentity();
    J.block(n, 0, l, p) = C;
    J.bottomRightCorner(l, l).setIdentity();
    Eigen::MatrixXd Pj = Eigen::MatrixXd::Zero(n + l, n + l);
    Pj.topLeftCorner(n, n) = P;
    Pj.bottomRightCorner(l, l) = R;
    Eigen::VectorXd xj(n + l);
    xj << x, z;
    x = J * xj;
    P = J * Pj * J.transpose();
  }
};

/// The linear-Gaussian test problem both tests run: the model, its matrices, the first state.
struct LinearScenario {
  std::shared_ptr<LinearSlamModel> model;
  Eigen::MatrixXd A, B, C, Q, R, P0;
  Eigen::VectorXd x0;
};

inline LinearScenario linear_scenario() {
  LinearScenario s;
  s.A = (Eigen::MatrixXd(2, 2) << 1.0, 0.1, -0.05, 0.95).finished();
  s.B = (Eigen::MatrixXd(2, 2) << 1.0, 0.0, 0.2, 1.0).finished();
  s.C = (Eigen::MatrixXd(2, 2) << 1.0, 0.0, 0.3, 1.0).finished();
  s.Q = (Eigen::MatrixXd(2, 2) << 0.04, 0.01, 0.01, 0.09).finished();
  s.R = (Eigen::MatrixXd(2, 2) << 0.25, -0.05, -0.05, 0.16).finished();
  s.P0 = (Eigen::MatrixXd(2, 2) << 0.5, 0.1, 0.1, 0.3).finished();
  s.x0 = Eigen::Vector2d(1.0, -1.0);
  s.model = std::make_shared<LinearSlamModel>(s.A, s.B, s.C);
  return s;
}

}  // namespace sextant::test
