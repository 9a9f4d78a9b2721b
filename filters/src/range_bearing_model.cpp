#include "sextant/filters/range_bearing_model.hpp"

#include <cmath>

#include "sextant/core/pose.hpp"

namespace sextant {

bool RangeBearingModelSettings::valid(std::string* why) const {
  if (!(dt > 0.0)) return *why = "dt must be > 0", false;
  if (!(wheelbase > 0.0)) return *why = "wheelbase must be > 0", false;
  return true;
}

// eq. (5.7)
Eigen::VectorXd RangeBearingModel::process(const Eigen::VectorXd& pose, const Eigen::VectorXd& u) const {
  const double V = u[0], g = u[1], heading = pose[2] + g;
  Eigen::VectorXd next(3);
  next << pose[0] + V * s_.dt * std::cos(heading), pose[1] + V * s_.dt * std::sin(heading),
      wrap_angle(pose[2] + V * s_.dt * std::sin(g) / s_.wheelbase);
  return next;
}

Eigen::MatrixXd RangeBearingModel::process_jacobian_pose(const Eigen::VectorXd& pose,
                                                         const Eigen::VectorXd& u) const {
  const double V = u[0], heading = pose[2] + u[1];
  Eigen::MatrixXd F = Eigen::MatrixXd::Identity(3, 3);
  F(0, 2) = -V * s_.dt * std::sin(heading);
  F(1, 2) = V * s_.dt * std::cos(heading);
  return F;
}

// eq. (3.39), the same Ackermann form.
Eigen::MatrixXd RangeBearingModel::process_jacobian_control(const Eigen::VectorXd& pose,
                                                            const Eigen::VectorXd& u) const {
  const double V = u[0], g = u[1], heading = pose[2] + g;
  Eigen::MatrixXd G(3, 2);
  G << s_.dt * std::cos(heading), -V * s_.dt * std::sin(heading),  //
      s_.dt * std::sin(heading), V * s_.dt * std::cos(heading),    //
      s_.dt * std::sin(g) / s_.wheelbase, V * s_.dt * std::cos(g) / s_.wheelbase;
  return G;
}

// eq. (5.8)
Eigen::VectorXd RangeBearingModel::observe(const Eigen::VectorXd& pose, const Eigen::VectorXd& m) const {
  const double dx = m[0] - pose[0], dy = m[1] - pose[1];
  Eigen::VectorXd z(2);
  z << std::hypot(dx, dy), wrap_angle(std::atan2(dy, dx) - pose[2]);
  return z;
}

Eigen::MatrixXd RangeBearingModel::observe_jacobian_pose(const Eigen::VectorXd& pose,
                                                         const Eigen::VectorXd& m) const {
  const double dx = m[0] - pose[0], dy = m[1] - pose[1];
  const double q = dx * dx + dy * dy, r = std::sqrt(q);
  Eigen::MatrixXd H(2, 3);
  H << -dx / r, -dy / r, 0.0, dy / q, -dx / q, -1.0;
  return H;
}

Eigen::MatrixXd RangeBearingModel::observe_jacobian_landmark(const Eigen::VectorXd& pose,
                                                             const Eigen::VectorXd& m) const {
  return -observe_jacobian_pose(pose, m).leftCols(2);
}

// eq. (5.9)
Eigen::VectorXd RangeBearingModel::augment(const Eigen::VectorXd& pose, const Eigen::VectorXd& z) const {
  const double a = pose[2] + z[1];
  Eigen::VectorXd m(2);
  m << pose[0] + z[0] * std::cos(a), pose[1] + z[0] * std::sin(a);
  return m;
}

Eigen::MatrixXd RangeBearingModel::augment_jacobian_pose(const Eigen::VectorXd& pose,
                                                         const Eigen::VectorXd& z) const {
  const double a = pose[2] + z[1];
  Eigen::MatrixXd G(2, 3);
  G << 1.0, 0.0, -z[0] * std::sin(a), 0.0, 1.0, z[0] * std::cos(a);
  return G;
}

Eigen::MatrixXd RangeBearingModel::augment_jacobian_observation(const Eigen::VectorXd& pose,
                                                                const Eigen::VectorXd& z) const {
  const double a = pose[2] + z[1];
  Eigen::MatrixXd G(2, 2);
  G << std::cos(a), -z[0] * std::sin(a), std::sin(a), z[0] * std::cos(a);
  return G;
}

LinearSlamModel::LinearSlamModel(Eigen::MatrixXd A, Eigen::MatrixXd B, Eigen::MatrixXd C)
    : A_(std::move(A)), B_(std::move(B)), C_(std::move(C)) {}

Eigen::VectorXd LinearSlamModel::process(const Eigen::VectorXd& pose, const Eigen::VectorXd& u) const {
  return A_ * pose + B_ * u;
}

Eigen::VectorXd LinearSlamModel::observe(const Eigen::VectorXd& pose, const Eigen::VectorXd& m) const {
  return m - C_ * pose;
}

Eigen::MatrixXd LinearSlamModel::observe_jacobian_landmark(const Eigen::VectorXd&,
                                                           const Eigen::VectorXd&) const {
  return Eigen::MatrixXd::Identity(C_.rows(), C_.rows());
}

Eigen::VectorXd LinearSlamModel::augment(const Eigen::VectorXd& pose, const Eigen::VectorXd& z) const {
  return z + C_ * pose;
}

Eigen::MatrixXd LinearSlamModel::augment_jacobian_observation(const Eigen::VectorXd&,
                                                              const Eigen::VectorXd&) const {
  return Eigen::MatrixXd::Identity(C_.rows(), C_.rows());
}

}  // namespace sextant
