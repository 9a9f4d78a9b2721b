#pragma once
// Planar poses and the square the posegraph tests drive around, lap after lap.
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

namespace sextant::test {

using PoseList = std::vector<Eigen::Isometry3d>;

/// The pose at (x, y, 0) [m] turned by `yaw` [rad] about z.
inline Eigen::Isometry3d planar_pose(double x, double y, double yaw) {
  return Eigen::Translation3d(x, y, 0) * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
}

/// A 40 × 40 m square driven `laps` times (2 m steps, 80 poses a lap): pose 80·l + k is pose k.
inline PoseList square_drive(int laps) {
  PoseList truth;
  const Eigen::Vector2d corner[4] = {{0, 0}, {40, 0}, {40, 40}, {0, 40}};
  for (int lap = 0; lap < laps; ++lap)
    for (int side = 0; side < 4; ++side)
      for (int step = 0; step < 20; ++step) {
        const double yaw = side * M_PI / 2.0, along = 2.0 * step;
        truth.push_back(planar_pose(corner[side].x() + along * std::cos(yaw),
                                    corner[side].y() + along * std::sin(yaw), yaw));
      }
  return truth;
}

}  // namespace sextant::test
