#pragma once
// The frame one odometry step registers in (registration_centre.hpp): the scans' own coordinates
// when a sensor could stand at their origin (scans in their sensor frame: nothing moves), else copies
// centred on the reference (scans exported in a map frame, or georeferenced). The step's priors go
// in, its transforms and Hessian come back out.
#include <vector>

#include "sextant/matchers/registration_centre.hpp"
#include "sextant/odometry/odometry.hpp"

namespace sextant::odometry_detail {

class StepFrame {
 public:
  StepFrame(const PointCloud& reference, const PointCloud& input);
  StepFrame(const StepFrame&) = delete;
  StepFrame& operator=(const StepFrame&) = delete;

  const PointCloud& reference() const { return frame_.moved() ? local_reference_ : reference_; }
  const PointCloud& input() const { return frame_.moved() ? local_input_ : input_; }
  /// Whether the scans lie in their sensor's frame (a sensor could stand at their origin).
  bool sensor_frame() const { return !frame_.moved(); }
  Eigen::Isometry3d local(const Eigen::Isometry3d& T) const { return frame_.local(T); }
  std::vector<Eigen::Isometry3d> local(std::vector<Eigen::Isometry3d> transforms) const;
  /// The step's relative pose, guess, first registration and Hessian in the scans' coordinates.
  void to_coordinates(OdometryStep& step) const;

 private:
  const PointCloud& reference_;
  const PointCloud& input_;
  CentredFrame frame_;
  PointCloud local_reference_, local_input_;  ///< only when the frame moved
};

}  // namespace sextant::odometry_detail
