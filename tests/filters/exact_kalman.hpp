#pragma once
// The exact Kalman filter over the joint state [pose; landmarks] of the linear-Gaussian SLAM
// model (LinearSlamModel: x' = A x + B u, z = m − C x, m = C x + z), written densely and
// independently of the filters: the reference of linear_gaussian_test.cpp and fastslam_test.cpp.
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

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

}  // namespace sextant::test
