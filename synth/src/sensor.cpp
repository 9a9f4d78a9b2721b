#include "sextant/synth/sensor.hpp"
#include "sextant/core/units.hpp"

#include <cmath>
#include <map>

namespace sextant::synth {
SimulatedScan simulate_scan(const World& world, const SensorSettings& sensor, double sensor_height,
                            const Eigen::Isometry3d& world_from_sensor, Rng& rng) {
  SimulatedScan scan;
  const int ne = sensor.elevation_steps;
  std::vector<double> cos_e(ne), sin_e(ne);
  for (int j = 0; j < ne; ++j) {
    const double e =
        (sensor.elevation_min_deg + (sensor.elevation_max_deg - sensor.elevation_min_deg) * j / (ne - 1)) *
        kPi / 180;
    cos_e[j] = std::cos(e);
    sin_e[j] = std::sin(e);
  }
  // The vehicle body below the scanner (sensor frame): rays that hit it are self-hits.
  const Box body{{-0.5 * sensor.body_length, -0.5 * sensor.body_width, -sensor_height},
                 {0.5 * sensor.body_length, 0.5 * sensor.body_width, sensor.body_top}};
  const Eigen::Matrix3d R = world_from_sensor.linear();
  Ray ray;
  ray.origin = world_from_sensor.translation();
  std::map<int, std::size_t> per_landmark;
  const std::size_t rays = static_cast<std::size_t>(sensor.yaw_steps) * ne;
  scan.cloud.reserve(rays);
  for (int k = 0; k < sensor.yaw_steps; ++k) {
    const double yaw = 2 * kPi * k / sensor.yaw_steps;
    const double cy = std::cos(yaw), sy = std::sin(yaw);
    for (int j = 0; j < ne; ++j) {
      const std::uint64_t key = rng.bits();
      const double noise = rng.normal(0.0, sensor.range_noise);
      ++scan.stats.rays;
      const Eigen::Vector3d dir_s(cos_e[j] * cy, cos_e[j] * sy, sin_e[j]);
      // A body below the scanner cannot be hit by a ray that does not go down.
      const bool may_hit_body = dir_s.z() < 0.0 || body.max.z() >= 0.0;
      const auto self =
          may_hit_body ? body.intersect(Ray{Eigen::Vector3d::Zero(), dir_s}, sensor.max_range) : std::nullopt;
      ray.direction = R * dir_s;
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
      scan.primitive.push_back(hit->primitive);
      scan.landmark.push_back(hit->landmark);
      if (hit->landmark >= 0) ++per_landmark[hit->landmark];
    }
  }
  scan.stats.returns = scan.cloud.size();
  for (const auto& [id, count] : per_landmark) scan.visible.push_back({id, count});
  return scan;
}

}  // namespace sextant::synth
