#pragma once
// Kalman filters that fuse odometry with scan-matching poses (§3.4).
//   ScanMatchingKf3d — the linear KF of Table 3.3 over the 6D pose parameters: control
//     u(k) = x_o(k) − x_o(k−1) from odometry, measurement z = the pose given by the matcher,
//     R = H⁻¹ from the matcher's Hessian (eq. 3.50). When matcher and odometry disagree beyond
//     the thresholds (or the matcher failed / H is not positive definite) the step raises an
//     alarm and keeps the odometry prediction (§5.1.3.2). Table 3.3 takes z as a pose measured on its
//     own; z = x̂(k|k) ⊕ T carries the filter's own error, so with `relative` the same registration is
//     fused as what it is, a second measurement of the increment beside u (KfMeasurement).
//   AckermannScanMatchingEkf — the 2D EKF of eqs. (3.37)–(3.52): Ackermann prediction, relative
//     scan-matching measurement ξ = (t_x, t_y, γ) (eq. 3.46) taken from the previous estimate.
#include <string>

#include <Eigen/Core>

#include "sextant/core/pose.hpp"
#include "sextant/filters/range_bearing_model.hpp"

namespace sextant {

/// How ScanMatchingKf3d fuses the matcher's pose z = x̂(k|k) ⊕ T.
///   absolute — Table 3.3: z as an independent pose measurement, S = P(k+1|k) + R. Its error holds the
///              filter's own error e(k), which the innovation's covariance leaves out, so P(k|k) ≤ R stays
///              bounded while the chained error grows.
///   relative — the exact filter for that z: u = d + w (w ~ Q) and T = d + v (v ~ R) are two measurements
///              of one increment d, and ε = z − x̂(k+1|k) = T − u holds no e(k): S = Q + R, K = Q S⁻¹,
///              P(k+1|k+1) = P(k|k) + Q − Q S⁻¹ Q = P(k|k) + (Q⁻¹ + R⁻¹)⁻¹ (the increments' best linear
///              fusion added to the error so far).
enum class KfMeasurement { absolute, relative };

struct ScanMatchingKfSettings {
  double odometry_sigma_translation = 0.25;  ///< σ of each translation entry of Q [m]
  double odometry_sigma_rotation = 0.01745;  ///< σ of each angle entry of Q [rad]
  double alarm_translation = 0.5;            ///< ‖Δt_matcher − Δt_odometry‖ raising the alarm [m]
  double alarm_rotation = 0.0873;  ///< max |Δangle_matcher − Δangle_odometry| raising the alarm [rad]
  KfMeasurement measurement = KfMeasurement::absolute;  ///< Table 3.3's, or the exact relative fusion
  bool valid(std::string* why) const;
  Matrix6d process_noise() const;  ///< Q = diag(σ_t², σ_t², σ_t², σ_r², σ_r², σ_r²)
};

struct ScanMatchingKfStep {
  Pose6 pose;  ///< x̂(k+1|k+1)
  Matrix6d P = Matrix6d::Identity();
  bool alarm = false;  ///< matcher rejected; the odometry prediction was kept
  std::string reason;  ///< why the alarm was raised (empty without alarm)
};

class ScanMatchingKf3d {
 public:
  ScanMatchingKf3d(ScanMatchingKfSettings settings, const Pose6& initial, const Matrix6d& P0);
  /// One step of Table 3.3. u: odometry increment in pose parameters (x_o(k) − x_o(k−1));
  /// matcher_pose: the matcher's pose for the new scan; H: its Hessian (R = H⁻¹).
  ScanMatchingKfStep step(const Vector6d& u, const Pose6& matcher_pose, const Matrix6d& H,
                          bool matcher_converged = true);
  const Pose6& pose() const { return pose_; }
  const Matrix6d& covariance() const { return P_; }

 private:
  ScanMatchingKfSettings s_;
  Pose6 pose_;
  Matrix6d P_;
};

/// The matcher's absolute pose for the new scan: previous pose ⊕ relative transform.
Pose6 chain_pose(const Pose6& previous, const Eigen::Isometry3d& relative);

class AckermannScanMatchingEkf {
 public:
  AckermannScanMatchingEkf(RangeBearingModelSettings vehicle, const Eigen::Vector3d& initial,
                           const Eigen::Matrix3d& P0);
  /// eqs. (3.48)–(3.49): u = (V, γ), Q its covariance.
  void predict(const Eigen::Vector2d& u, const Eigen::Matrix2d& Q);
  /// eqs. (3.50)–(3.52): ξ = (t_x, t_y, γ) from the pose at the last update to the current one.
  /// Returns false (state unchanged) when the innovation covariance is singular.
  bool update(const Eigen::Vector3d& xi, const Eigen::Matrix3d& R);
  const Eigen::Vector3d& pose() const { return x_; }
  const Eigen::Matrix3d& covariance() const { return P_; }
  /// eq. (3.46) and its Jacobian with respect to the current pose (the reference pose is fixed).
  static Eigen::Vector3d relative_measurement(const Eigen::Vector3d& from, const Eigen::Vector3d& to);
  static Eigen::Matrix3d relative_jacobian(const Eigen::Vector3d& from);

 private:
  RangeBearingModel vehicle_;
  Eigen::Vector3d x_, reference_;
  Eigen::Matrix3d P_;
};

}  // namespace sextant
