#pragma once
// The simulated 3D laser: a 2D scanner whose scan plane is vertical, rotated about the
// vertical axis (yaw scan) as on the thesis' robot. Rays converge at the rotation axis, so
// the density is high near the vehicle and falls with range (thesis figs 2.3–2.5). Or
// (SensorSettings::pattern "rosette") a solid-state lidar: a non-repetitive rosette over a fixed
// field of view, another part of it at every scan (issue 62).
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/synth/settings.hpp"
#include "sextant/synth/world.hpp"

namespace sextant::synth {

/// How many points of a scan fell on one true planar landmark.
struct LandmarkVisibility {
  int landmark = 0;
  std::size_t points = 0;
};

struct ScanStatistics {
  std::size_t rays = 0;
  std::size_t returns = 0;    ///< points kept
  std::size_t no_return = 0;  ///< nothing within max_range
  std::size_t self_hits = 0;  ///< ray hit the vehicle body, or the return was closer than min_range
};

/// One simulated scan in the sensor frame, with what every point hit.
struct SimulatedScan {
  PointCloud cloud;                         ///< sensor frame (x forward, y left, z up) [m]
  std::vector<std::int32_t> primitive;      ///< per point: index into World::primitives
  std::vector<std::int32_t> landmark;       ///< per point: landmark id or −1
  std::vector<LandmarkVisibility> visible;  ///< landmarks with at least one point, by id
  ScanStatistics stats;
};

/// Casts every ray of one scan from the world ← sensor pose. Deterministic in (pose, rng state).
SimulatedScan simulate_scan(const World& world, const SensorSettings& sensor, double sensor_height,
                            const Eigen::Isometry3d& world_from_sensor, Rng& rng);

}  // namespace sextant::synth
