#pragma once
// 2D range–bearing SLAM over point landmarks (§5.2.1.3 A, eqs. 5.7–5.9):
//   pose (x, y, φ), control u = (V, γ) = (speed [m/s], steering angle [rad]),
//   landmark (x_m, y_m), observation z = (r, b) = (range [m], bearing [rad]).
#include "sextant/filters/slam_model.hpp"

namespace sextant {

struct RangeBearingModelSettings {
  double dt = 0.05;        ///< time between two controls [s]
  double wheelbase = 4.0;  ///< L, vehicle wheelbase [m]
  bool valid(std::string* why) const;
};

class RangeBearingModel final : public SlamModel {
 public:
  explicit RangeBearingModel(RangeBearingModelSettings settings = {}) : s_(settings) {}
  const RangeBearingModelSettings& settings() const { return s_; }

  std::string name() const override { return "range_bearing2d"; }
  int pose_dim() const override { return 3; }
  int control_dim() const override { return 2; }
  int landmark_dim() const override { return 2; }
  int observation_dim() const override { return 2; }

  Eigen::VectorXd process(const Eigen::VectorXd& pose, const Eigen::VectorXd& u) const override;
  Eigen::MatrixXd process_jacobian_pose(const Eigen::VectorXd& pose, const Eigen::VectorXd& u) const override;
  Eigen::MatrixXd process_jacobian_control(const Eigen::VectorXd& pose,
                                           const Eigen::VectorXd& u) const override;
  Eigen::VectorXd observe(const Eigen::VectorXd& pose, const Eigen::VectorXd& landmark) const override;
  Eigen::MatrixXd observe_jacobian_pose(const Eigen::VectorXd& pose,
                                        const Eigen::VectorXd& landmark) const override;
  Eigen::MatrixXd observe_jacobian_landmark(const Eigen::VectorXd& pose,
                                            const Eigen::VectorXd& landmark) const override;
  Eigen::VectorXd augment(const Eigen::VectorXd& pose, const Eigen::VectorXd& z) const override;
  Eigen::MatrixXd augment_jacobian_pose(const Eigen::VectorXd& pose, const Eigen::VectorXd& z) const override;
  Eigen::MatrixXd augment_jacobian_observation(const Eigen::VectorXd& pose,
                                               const Eigen::VectorXd& z) const override;

  std::vector<int> pose_angles() const override { return {2}; }
  std::vector<int> observation_angles() const override { return {1}; }

 private:
  RangeBearingModelSettings s_;
};

/// A linear-Gaussian test problem with the same layout: f = A·x_v + B·u, h = m − C·x_v,
/// g = z + C·x_v (dimensions from the matrices; landmark and observation sizes equal C.rows()).
/// Every Gaussian filter is exact on it, so it is the reference for the exact Kalman filter.
class LinearSlamModel final : public SlamModel {
 public:
  LinearSlamModel(Eigen::MatrixXd A, Eigen::MatrixXd B, Eigen::MatrixXd C);
  std::string name() const override { return "linear"; }
  int pose_dim() const override { return static_cast<int>(A_.rows()); }
  int control_dim() const override { return static_cast<int>(B_.cols()); }
  int landmark_dim() const override { return static_cast<int>(C_.rows()); }
  int observation_dim() const override { return static_cast<int>(C_.rows()); }

  Eigen::VectorXd process(const Eigen::VectorXd& pose, const Eigen::VectorXd& u) const override;
  Eigen::MatrixXd process_jacobian_pose(const Eigen::VectorXd&, const Eigen::VectorXd&) const override {
    return A_;
  }
  Eigen::MatrixXd process_jacobian_control(const Eigen::VectorXd&, const Eigen::VectorXd&) const override {
    return B_;
  }
  Eigen::VectorXd observe(const Eigen::VectorXd& pose, const Eigen::VectorXd& landmark) const override;
  Eigen::MatrixXd observe_jacobian_pose(const Eigen::VectorXd&, const Eigen::VectorXd&) const override {
    return -C_;
  }
  Eigen::MatrixXd observe_jacobian_landmark(const Eigen::VectorXd&, const Eigen::VectorXd&) const override;
  Eigen::VectorXd augment(const Eigen::VectorXd& pose, const Eigen::VectorXd& z) const override;
  Eigen::MatrixXd augment_jacobian_pose(const Eigen::VectorXd&, const Eigen::VectorXd&) const override {
    return C_;
  }
  Eigen::MatrixXd augment_jacobian_observation(const Eigen::VectorXd&, const Eigen::VectorXd&) const override;

 private:
  Eigen::MatrixXd A_, B_, C_;
};

}  // namespace sextant
