#pragma once
// The simulated 3D laser: a 2D scanner whose scan plane is vertical, rotated about the
// vertical axis (yaw scan) as on the thesis' robot. Rays converge at the rotation axis, so
// the density is high near the vehicle and falls with range (thesis figs 2.3–2.5). Or
// (SensorSettings::pattern "rosette") a solid-state lidar: a non-repetitive rosette over a fixed
// field of view, another part of it at every scan (issue 62). Either scans at once or sweeps while it
// moves (SensorSettings::sweep_period, issue 63).
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

/// How the sensor moves while it sweeps (SensorSettings::sweep_period > 0): at a constant velocity, it
/// makes `motion` (in its frame at the sweep's start) in `seconds`.
struct SensorMotion {
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  double seconds = 0.0;
};

/// Casts every ray of one scan from the world ← sensor pose. With a sweep_period, the ray taken at time
/// τ along the sweep is cast from world_from_sensor · interpolate_motion(moving.motion, τ / moving.seconds)
/// (core/se3.hpp) and its point carries τ; without, every ray from world_from_sensor. Deterministic in
/// (pose, motion, rng state); the rng draws the same numbers either way.
SimulatedScan simulate_scan(const World& world, const SensorSettings& sensor, double sensor_height,
                            const Eigen::Isometry3d& world_from_sensor, Rng& rng,
                            const SensorMotion& moving = {});

}  // namespace sextant::synth
