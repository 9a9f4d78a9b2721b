#include "sextant/synth/campus.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <tbb/parallel_for.h>

#include "sextant/core/pose.hpp"
#include "sextant/synth/odometry.hpp"
#include "sextant/synth/route.hpp"
#include "sextant/synth/world_builder.hpp"

namespace sextant::synth {
namespace {

/// Independent random streams per purpose (and per scan), derived from the seed.
enum Stream : std::uint64_t { kWorld = 1, kRoute = 2, kOdometry = 3, kGnss = 4, kScans = 1000 };

std::uint64_t mix(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t x = seed ^ (stream * 0x9E3779B97F4A7C15ULL);
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

}  // namespace

SimulatedScan Campus::scan(std::size_t i) const {
  if (i >= ground_truth.size())
    throw std::out_of_range("campus scan " + std::to_string(i) + " does not exist");
  Rng rng(mix(seed, kScans + first_scan + i));
  SensorMotion moving;
  if (settings.sensor.sweep_period > 0.0) {
    const Eigen::Isometry3d& next = i + 1 < ground_truth.size() ? ground_truth[i + 1] : pose_after_last;
    moving = {relative(ground_truth[i], next), settings.trajectory.scan_period};
  }
  return simulate_scan(*world, settings.sensor, settings.trajectory.sensor_height, ground_truth[i], rng,
                       moving);
}

Campus campus_window(const Campus& campus, std::size_t first, std::size_t count) {
  if (first > campus.size() || count > campus.size() - first)
    throw std::out_of_range("campus scans " + std::to_string(first) + " + " + std::to_string(count) +
                            " go past its " + std::to_string(campus.size()) + " scans");
  const auto slice = [&](const auto& v) {  // every per-scan vector has the campus' size
    const auto b = static_cast<std::ptrdiff_t>(std::min(first, v.size()));
    const auto e = static_cast<std::ptrdiff_t>(std::min(first + count, v.size()));
    return std::decay_t<decltype(v)>(v.begin() + b, v.begin() + e);
  };
  Campus window;
  window.settings = campus.settings;
  window.seed = campus.seed;
  window.world = campus.world;
  window.ground_truth = slice(campus.ground_truth);
  window.odometry = slice(campus.odometry);
  window.stamps = slice(campus.stamps);
  window.gnss = slice(campus.gnss);
  window.first_scan = campus.first_scan + first;
  window.pose_after_last =
      first + count < campus.size() ? campus.ground_truth[first + count] : campus.pose_after_last;
  return window;
}

Campus generate_campus(const CampusSettings& settings, std::uint64_t seed) {
  std::string why;
  if (!settings.valid(&why)) throw std::invalid_argument("invalid campus settings: " + why);
  Campus campus;
  campus.settings = settings;
  campus.seed = seed;
  Rng world_rng(mix(seed, kWorld));
  // Keep the west border clear of the approach leg (and its wander) before the sharp turn.
  const double clearance =
      start_leg_length(settings.world, settings.trajectory) + settings.world.road_half_width;
  auto world = std::make_shared<World>(build_world(settings.world, clearance, world_rng));
  Rng route_rng(mix(seed, kRoute));
  for (const RoutePoint& p : sample_route(settings.world, settings.trajectory, route_rng)) {
    Eigen::Isometry3d pose = ground_following_pose(*world, settings.trajectory, p);
    if (settings.trajectory.platform == "handheld")
      pose.linear() = pose.linear() * handheld_sway(settings.trajectory, campus.ground_truth.size());
    campus.ground_truth.push_back(pose);
  }
  campus.world = std::move(world);
  const std::vector<Eigen::Isometry3d>& route = campus.ground_truth;
  campus.pose_after_last =
      route.size() < 2 ? route.back() : route.back() * relative(route[route.size() - 2], route.back());
  for (std::size_t i = 0; i < campus.ground_truth.size(); ++i)
    campus.stamps.push_back(static_cast<double>(i) * settings.trajectory.scan_period);
  Rng odometry_rng(mix(seed, kOdometry));
  campus.odometry = simulate_odometry(campus.ground_truth, settings.odometry, odometry_rng);
  Rng gnss_rng(mix(seed, kGnss));
  campus.gnss = simulate_gnss(campus.ground_truth, campus.stamps, settings.gnss, gnss_rng);
  // first_scans: the first N poses of the same route (everything above was drawn for the whole
  // route, so they equal the full campus' first N).
  if (settings.trajectory.first_scans > 0) {
    const auto n = static_cast<std::size_t>(settings.trajectory.first_scans);
    if (n < campus.ground_truth.size()) campus.pose_after_last = campus.ground_truth[n];
    campus.ground_truth.resize(n);
    campus.odometry.resize(n);
    campus.stamps.resize(n);
    campus.gnss.resize(n);
  }
  return campus;
}

std::vector<SimulatedScan> generate_all_scans(const Campus& campus) {
  std::vector<SimulatedScan> scans(campus.size());
  tbb::parallel_for(std::size_t{0}, campus.size(), [&](std::size_t i) { scans[i] = campus.scan(i); });
  return scans;
}

CampusDataset::CampusDataset(Campus campus) : campus_(std::move(campus)) {
  metadata_.name = "synthetic-campus-" + std::to_string(campus_.seed);
  metadata_.format = "synthetic";
  metadata_.scan_count = campus_.size();
  metadata_.has_odometry = true;
  metadata_.has_ground_truth = true;
}

PointCloud CampusDataset::scan(std::size_t i, ScanLoadReport* report) const {
  SimulatedScan s = campus_.scan(i);
  if (report) {
    *report = ScanLoadReport{};
    report->points_read = s.cloud.size();
  }
  return std::move(s.cloud);
}

std::optional<Eigen::Isometry3d> CampusDataset::odometry(std::size_t i) const {
  if (i >= campus_.size()) return std::nullopt;
  return campus_.odometry[i];
}

std::optional<Eigen::Isometry3d> CampusDataset::ground_truth(std::size_t i) const {
  if (i >= campus_.size()) return std::nullopt;
  return campus_.ground_truth[i];
}

}  // namespace sextant::synth
