#pragma once
// What run_odometry hands its scan observer (private to Sextant::odometry): each scan with its pose as
// soon as the pose is final, chained as run_odometry chains OdometryResult::poses (the same products
// in the same order: the same bits).
#include <cstddef>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/odometry/odometry.hpp"

namespace sextant::odometry_detail {

class ScanHandout {
 public:
  /// `observe` may be empty (nothing is handed out); it must outlive the handout.
  ScanHandout(const OdometryScanObserver& observe, const Eigen::Isometry3d& start)
      : observe_(observe), pose_(start) {}
  /// The sequence's first scan, at the start pose.
  void first(const PointCloud& scan) const {
    if (observe_) observe_(RegisteredScan{0, &scan, pose_, nullptr});
  }
  /// Scan k, placed by `step` (which links it to scan k − 1, the one handed out before).
  void next(std::size_t k, const PointCloud& scan, const OdometryStep& step) {
    pose_ = pose_ * step.relative;
    if (observe_) observe_(RegisteredScan{k, &scan, pose_, &step});
  }

 private:
  const OdometryScanObserver& observe_;
  Eigen::Isometry3d pose_;
};

}  // namespace sextant::odometry_detail
