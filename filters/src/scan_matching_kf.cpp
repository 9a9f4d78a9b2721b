#include "sextant/filters/scan_matching_kf.hpp"

#include <cmath>

#include <Eigen/Cholesky>

namespace sextant {

bool ScanMatchingKfSettings::valid(std::string* why) const {
  if (!(odometry_sigma_translation > 0 && odometry_sigma_rotation > 0))
    return *why = "odometry sigmas must be > 0", false;
  if (!(alarm_translation > 0 && alarm_rotation > 0)) return *why = "alarm thresholds must be > 0", false;
  return true;
}

Matrix6d ScanMatchingKfSettings::process_noise() const {
  Vector6d d;
  const double t = odometry_sigma_translation * odometry_sigma_translation;
  const double r = odometry_sigma_rotation * odometry_sigma_rotation;
  d << t, t, t, r, r, r;
  return d.asDiagonal();
}

ScanMatchingKf3d::ScanMatchingKf3d(ScanMatchingKfSettings settings, const Pose6& initial, const Matrix6d& P0)
    : s_(settings), pose_(initial), P_(P0) {}

// Table 3.3.
ScanMatchingKfStep ScanMatchingKf3d::step(const Vector6d& u, const Pose6& matcher_pose, const Matrix6d& H,
                                          bool matcher_converged) {
  Vector6d predicted = pose_.vector() + u;  // x̂(k+1|k) = x̂(k|k) + u(k)
  for (int i = 3; i < 6; ++i) predicted[i] = wrap_angle(predicted[i]);
  const Matrix6d P_pred = P_ + s_.process_noise();  // P(k+1|k) = P(k|k) + Q

  ScanMatchingKfStep out;
  Vector6d innovation = matcher_pose.vector() - predicted;  // ε = z(k+1) − ẑ(k+1|k)
  for (int i = 3; i < 6; ++i) innovation[i] = wrap_angle(innovation[i]);
  Eigen::LLT<Matrix6d> H_llt(0.5 * (H + H.transpose()));
  if (!matcher_converged || !is_finite(matcher_pose)) {
    out.alarm = true;
    out.reason = "matcher did not converge";
  } else if (!H.allFinite() || H_llt.info() != Eigen::Success) {
    out.alarm = true;
    out.reason = "matcher Hessian not positive definite";
  } else if (innovation.head<3>().norm() > s_.alarm_translation) {
    out.alarm = true;
    out.reason = "matcher and odometry disagree in translation";
  } else if (innovation.tail<3>().cwiseAbs().maxCoeff() > s_.alarm_rotation) {
    out.alarm = true;
    out.reason = "matcher and odometry disagree in rotation";
  }
  if (out.alarm) {  // §5.1.3.2: odometry is used for this step
    pose_ = Pose6::from_vector(predicted);
    P_ = P_pred;
  } else {
    const Matrix6d R = H_llt.solve(Matrix6d::Identity());  // R = H⁻¹, eq. (3.50)
    const bool relative = s_.measurement == KfMeasurement::relative;
    const Matrix6d Q = s_.process_noise();
    // Table 3.3: S = P + R, K = P S⁻¹. Relative (KfMeasurement): the innovation T − u holds no e(k).
    const Matrix6d& gain_of = relative ? Q : P_pred;
    const Matrix6d S = gain_of + R;
    const Matrix6d K = S.transpose().llt().solve(gain_of.transpose()).transpose();  // K = gain_of S⁻¹
    Vector6d updated = predicted + K * innovation;
    for (int i = 3; i < 6; ++i) updated[i] = wrap_angle(updated[i]);
    pose_ = Pose6::from_vector(updated);
    P_ = relative ? Matrix6d(P_ + Q - K * Q) : Matrix6d((Matrix6d::Identity() - K) * P_pred);
    P_ = 0.5 * (P_ + P_.transpose()).eval();
  }
  out.pose = pose_;
  out.P = P_;
  return out;
}

Pose6 chain_pose(const Pose6& previous, const Eigen::Isometry3d& relative) {
  return to_pose6(compose(to_isometry(previous), relative));
}

AckermannScanMatchingEkf::AckermannScanMatchingEkf(RangeBearingModelSettings vehicle,
                                                   const Eigen::Vector3d& initial, const Eigen::Matrix3d& P0)
    : vehicle_(vehicle), x_(initial), reference_(initial), P_(P0) {}

// eqs. (3.48)–(3.49)
void AckermannScanMatchingEkf::predict(const Eigen::Vector2d& u, const Eigen::Matrix2d& Q) {
  const Eigen::Matrix3d Gv = vehicle_.process_jacobian_pose(x_, u);
  const Eigen::MatrixXd Gu = vehicle_.process_jacobian_control(x_, u);
  x_ = vehicle_.process(x_, u);
  P_ = Gv * P_ * Gv.transpose() + Gu * Q * Gu.transpose();
}

// eq. (3.46)
Eigen::Vector3d AckermannScanMatchingEkf::relative_measurement(const Eigen::Vector3d& from,
                                                               const Eigen::Vector3d& to) {
  const double c = std::cos(from[2]), s = std::sin(from[2]);
  const double dx = to[0] - from[0], dy = to[1] - from[1];
  return {dx * c + dy * s, -dx * s + dy * c, wrap_angle(to[2] - from[2])};
}

Eigen::Matrix3d AckermannScanMatchingEkf::relative_jacobian(const Eigen::Vector3d& from) {
  const double c = std::cos(from[2]), s = std::sin(from[2]);
  Eigen::Matrix3d H;
  H << c, s, 0, -s, c, 0, 0, 0, 1;
  return H;
}

// eqs. (3.50)–(3.52)
bool AckermannScanMatchingEkf::update(const Eigen::Vector3d& xi, const Eigen::Matrix3d& R) {
  const Eigen::Matrix3d H = relative_jacobian(reference_);
  Eigen::Vector3d innovation = xi - relative_measurement(reference_, x_);
  innovation[2] = wrap_angle(innovation[2]);
  const Eigen::Matrix3d S = H * P_ * H.transpose() + R;
  Eigen::LLT<Eigen::Matrix3d> llt(0.5 * (S + S.transpose()));
  if (llt.info() != Eigen::Success || !xi.allFinite()) return false;
  const Eigen::Matrix3d K = llt.solve(H * P_).transpose();  // K = P Hᵀ S⁻¹
  x_ += K * innovation;
  x_[2] = wrap_angle(x_[2]);
  P_ = (Eigen::Matrix3d::Identity() - K * H) * P_;
  P_ = 0.5 * (P_ + P_.transpose()).eval();
  reference_ = x_;
  return true;
}

}  // namespace sextant
