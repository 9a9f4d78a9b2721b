#pragma once
// A small synthetic scene with known planes for the feature tests and benchmark: a ground plane,
// vertical walls (some not axis-aligned), clutter blobs (trees/bushes) and range noise.
#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/features/plane.hpp"
#include "sextant_test/random_draws.hpp"

namespace sextant::test {

/// The sensor pose at (x, y, z) [m], turned by `yaw_deg` about z.
inline Eigen::Isometry3d sensor_pose(double x, double y, double z, double yaw_deg) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

/// A vertical rectangular wall: from `start` along horizontal unit `direction` for `length`,
/// from z = start.z() up to `height`.
struct Wall {
  Eigen::Vector3d start;
  Eigen::Vector3d direction;
  double length;
  double height;

  Eigen::Vector3d normal() const { return Eigen::Vector3d::UnitZ().cross(direction).normalized(); }
  Plane plane() const { return Plane{normal(), normal().dot(start)}; }
  /// True when p (on or near the plane) lies within the wall rectangle grown by `margin`.
  bool contains(const Eigen::Vector3d& p, double margin) const {
    const Eigen::Vector3d q = p - start;
    const double along = q.dot(direction), up = q.z();
    return along > -margin && along < length + margin && up > -margin && up < height + margin;
  }
};

struct Scene {
  std::vector<Wall> walls;
  double ground_half_extent = 20.0;  ///< ground z = 0 over [−e, e]² [m]
  std::vector<Eigen::Vector3d> blob_centres;
};

/// A courtyard: six walls around the origin (two of them rotated), blobs inside.
inline Scene courtyard() {
  Scene s;
  auto dir = [](double deg) {
    const double a = deg * M_PI / 180.0;
    return Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
  };
  s.walls = {
      {{-15, 12, 0}, dir(0), 24, 8},     // north façade, normal −y after orientation
      {{14, -14, 0}, dir(90), 22, 10},   // east façade
      {{-12, -15, 0}, dir(0), 20, 6},    // south façade
      {{-18, 10, 0}, dir(-100), 18, 7},  // west façade, 10° off axis
      {{10, 12.5, 0}, dir(-35), 6, 5},   // a short wall across the north-east corner
      {{-6, -6, 0}, dir(30), 8, 3},      // a free-standing wall inside
  };
  s.blob_centres = {{5, 5, 2}, {-8, 4, 2.5}, {3, -9, 1.5}, {-10, -5, 2}, {8, -3, 2}};
  return s;
}

/// Samples the scene in the world frame and returns the points in the frame of `sensor_pose`
/// (p_sensor = T⁻¹ p_world). Densities are per square metre; noise is along the surface normal.
inline PointCloud sample_scene(const Scene& scene, const Eigen::Isometry3d& sensor_pose, Rng& rng,
                               double wall_density = 8.0, double ground_density = 3.0,
                               std::size_t blob_points = 300, double noise = 0.01) {
  std::vector<Eigen::Vector3d> world;
  for (const Wall& w : scene.walls) {
    const auto n = static_cast<std::size_t>(w.length * w.height * wall_density);
    for (std::size_t i = 0; i < n; ++i) {
      const double offset = rng.normal(0.0, noise), up = rng.uniform(0.0, w.height),
                   along = rng.uniform(0.0, w.length);
      world.push_back(w.start + w.direction * along + Eigen::Vector3d::UnitZ() * up + w.normal() * offset);
    }
  }
  const double e = scene.ground_half_extent;
  const auto ng = static_cast<std::size_t>(4.0 * e * e * ground_density);
  for (std::size_t i = 0; i < ng; ++i) {
    const double z = rng.normal(0.0, noise), y = rng.uniform(-e, e), x = rng.uniform(-e, e);
    world.emplace_back(x, y, z);
  }
  for (const auto& c : scene.blob_centres) {
    for (std::size_t i = 0; i < blob_points; ++i) {
      world.push_back(c + test::normal_draws<3>(rng, 0.8));
    }
  }
  const Eigen::Isometry3d to_sensor = sensor_pose.inverse();
  PointCloud cloud;
  cloud.reserve(world.size());
  for (const auto& p : world) cloud.push_back((to_sensor * p).cast<float>());
  return cloud;
}

}  // namespace sextant::test
