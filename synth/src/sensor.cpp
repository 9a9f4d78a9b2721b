#include "sextant/synth/sensor.hpp"
#include "sextant/core/se3.hpp"
#include "sextant/core/units.hpp"

#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace sextant::synth {
namespace {

/// The rosette's second frequency over its first: irrational (the golden ratio's square), so that the
/// curve never closes and every scan draws another part of it.
constexpr double kRosetteRatio = 2.6180339887498949;
/// Turns of the rosette's first frequency per scan: enough for the petals to fill the field of view.
constexpr double kRosetteTurns = 40.0;

/// The ray directions of one scan (sensor frame, x forward): a spinning scanner's yaw × elevation grid,
/// or the rosette (azimuth, elevation) = (h·cos(kφ)·cos φ, v·cos(kφ)·sin φ) over φ from a phase drawn for
/// the scan, with h and v the half fields of view: dense at the middle of the view, sparse at its edge,
/// as a Livox Avia's.
std::vector<Eigen::Vector3d> ray_directions(const SensorSettings& sensor, Rng& rng) {
  std::vector<Eigen::Vector3d> rays;
  if (sensor.pattern == "rosette") {
    const double phase = rng.uniform(0.0, 2.0 * kPi * 1.0e4);
    const double h = 0.5 * sensor.fov_horizontal_deg * kRadPerDeg,
                 v = 0.5 * sensor.fov_vertical_deg * kRadPerDeg;
    rays.reserve(static_cast<std::size_t>(sensor.rosette_rays));
    for (int k = 0; k < sensor.rosette_rays; ++k) {
      const double phi = phase + 2.0 * kPi * kRosetteTurns * k / sensor.rosette_rays;
      const double r = std::cos(kRosetteRatio * phi);
      const double azimuth = h * r * std::cos(phi), elevation = v * r * std::sin(phi);
      rays.emplace_back(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                        std::sin(elevation));
    }
    return rays;
  }
  const int ne = sensor.elevation_steps;
  rays.reserve(static_cast<std::size_t>(sensor.yaw_steps) * static_cast<std::size_t>(ne));
  for (int k = 0; k < sensor.yaw_steps; ++k) {
    const double yaw = 2 * kPi * k / sensor.yaw_steps;
    for (int j = 0; j < ne; ++j) {
      const double e =
          (sensor.elevation_min_deg + (sensor.elevation_max_deg - sensor.elevation_min_deg) * j / (ne - 1)) *
          kPi / 180;
      rays.emplace_back(std::cos(e) * std::cos(yaw), std::cos(e) * std::sin(yaw), std::sin(e));
    }
  }
  return rays;
}

/// When along the sweep ray `r` of `rays` is taken, as a fraction of the sweep: a spinning scanner's
/// yaw column over the turn (its rays are column by column), the rosette's ray over its rays.
double sweep_fraction(const SensorSettings& sensor, std::size_t r, std::size_t rays) {
  if (sensor.pattern == "rosette") return static_cast<double>(r) / static_cast<double>(rays);
  const auto column = r / static_cast<std::size_t>(sensor.elevation_steps);
  return static_cast<double>(column) / sensor.yaw_steps;
}

}  // namespace

SimulatedScan simulate_scan(const World& world, const SensorSettings& sensor, double sensor_height,
                            const Eigen::Isometry3d& world_from_sensor, Rng& rng,
                            const SensorMotion& moving) {
  SimulatedScan scan;
  const std::vector<Eigen::Vector3d> directions = ray_directions(sensor, rng);
  const bool sweeps = sensor.sweep_period > 0.0;
  std::vector<float> times;
  double pose_time = 0.0;  // the time `pose` is the sensor's at
  // The vehicle body below the scanner (sensor frame): rays that hit it are self-hits.
  const Box body{{-0.5 * sensor.body_length, -0.5 * sensor.body_width, -sensor_height},
                 {0.5 * sensor.body_length, 0.5 * sensor.body_width, sensor.body_top}};
  Eigen::Isometry3d pose = world_from_sensor;
  Ray ray;
  ray.origin = pose.translation();
  std::map<int, std::size_t> per_landmark;
  scan.cloud.reserve(directions.size());
  for (std::size_t r = 0; r < directions.size(); ++r) {
    const Eigen::Vector3d& dir_s = directions[r];
    const double time = sweeps ? sensor.sweep_period * sweep_fraction(sensor, r, directions.size()) : 0.0;
    if (time != pose_time && moving.seconds > 0.0) {
      pose_time = time;
      pose = world_from_sensor * interpolate_motion(moving.motion, time / moving.seconds);
      ray.origin = pose.translation();
    }
    const std::uint64_t key = rng.bits();
    const double noise = rng.normal(0.0, sensor.range_noise);
    ++scan.stats.rays;
    // A body below the scanner cannot be hit by a ray that does not go down.
    const bool may_hit_body = dir_s.z() < 0.0 || body.max.z() >= 0.0;
    const auto self =
        may_hit_body ? body.intersect(Ray{Eigen::Vector3d::Zero(), dir_s}, sensor.max_range) : std::nullopt;
    ray.direction = pose.linear() * dir_s;
    const auto hit = world.cast(ray, self ? *self : sensor.max_range, key);
    if (!hit) {
      ++(self ? scan.stats.self_hits : scan.stats.no_return);
      continue;
    }
    const double range = hit->range + noise;
    if (range < sensor.min_range || range > sensor.max_range) {
      ++(range < sensor.min_range ? scan.stats.self_hits : scan.stats.no_return);
      continue;
    }
    scan.cloud.push_back((range * dir_s).cast<float>());
    if (sweeps) times.push_back(static_cast<float>(time));
    scan.primitive.push_back(hit->primitive);
    scan.landmark.push_back(hit->landmark);
    if (hit->landmark >= 0) ++per_landmark[hit->landmark];
  }
  scan.stats.returns = scan.cloud.size();
  if (sweeps) scan.cloud.set_time(std::move(times));
  for (const auto& [id, count] : per_landmark) scan.visible.push_back({id, count});
  return scan;
}

}  // namespace sextant::synth
