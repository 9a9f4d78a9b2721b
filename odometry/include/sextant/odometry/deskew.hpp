#pragma once
// Undoing a sweeping lidar's motion (deskew): a scan's points are taken one after the other while the
// sensor moves, each at its own time (PointCloud::time, seconds from the scan's stamp) from where the
// sensor was then. Deskewing moves every point into the sensor's frame at the stamp (t = 0) by the
// motion the sensor made until the point's time, at a constant velocity (docs/odometry.md, "Scans
// taken while moving"):
//
//   p₀ = T(τ) · p_τ,   T(τ) = exp((τ / Δt) · log M)   (interpolate_motion, core/se3.hpp)
//
// where M is the motion the sensor makes in Δt (the velocity's estimate: the motion of a step and its
// duration).
#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"

namespace sextant {

/// The sensor's velocity over a sweep, as the motion M it makes in `seconds` (p_before = M · p_after).
struct SweepMotion {
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  double seconds = 0.0;  ///< the time M takes [s]; 0: no motion known, the scan is kept as read
  bool known() const { return seconds > 0.0; }
};

/// The scan with each point moved into the frame at the stamp (the formula above), without its times
/// (it is now one instant's). A scan without times, or a sweep without a known motion, is returned as
/// it is (times kept).
PointCloud deskew_scan(const PointCloud& scan, const SweepMotion& sweep);

/// Latest minus earliest point time of the scan [s]: how long its sweep took; 0 without times.
double sweep_span(const PointCloud& scan);

}  // namespace sextant
