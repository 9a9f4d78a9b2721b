// Deskewing a scan by a constant velocity (deskew.hpp).
#include "sextant/odometry/deskew.hpp"

#include <algorithm>

#include "sextant/core/se3.hpp"

namespace sextant {

PointCloud deskew_scan(const PointCloud& scan, const SweepMotion& sweep) {
  if (!scan.has_time() || !sweep.known()) return scan;
  const Vector6d velocity = se3_log(sweep.motion) / sweep.seconds;  // twist per second
  const std::vector<float>& time = scan.time();
  std::vector<Eigen::Vector3f> points;
  points.reserve(scan.size());
  // Drivers give the points of one firing (a column of rings) one time: one pose serves them all.
  float pose_time = 0.0f;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < scan.size(); ++i) {
    if (time[i] != pose_time) {
      pose_time = time[i];
      pose = se3_exp(static_cast<double>(pose_time) * velocity);
    }
    points.push_back((pose * scan[i].cast<double>()).cast<float>());
  }
  PointCloud out(std::move(points));
  if (scan.has_intensity()) out.intensity() = scan.intensity();
  return out;
}

double sweep_span(const PointCloud& scan) {
  if (!scan.has_time()) return 0.0;
  const auto [earliest, latest] = std::minmax_element(scan.time().begin(), scan.time().end());
  return static_cast<double>(*latest) - static_cast<double>(*earliest);
}

}  // namespace sextant
