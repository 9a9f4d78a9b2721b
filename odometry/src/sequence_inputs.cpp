// What run_odometry reads of a sequence beside its scans (sequence_inputs.hpp).
#include "sequence_inputs.hpp"

#include <cmath>
#include <limits>

#include "sextant/core/error.hpp"
#include "sextant/odometry/sequence_trust.hpp"

namespace sextant::odometry_detail {
namespace {

/// The times from scan i − 2 to i − 1 and from i − 1 to i, when the dataset stamps all three.
struct StepTimes {
  double before = 0.0, now = 0.0;  ///< [s]
};
std::optional<StepTimes> step_times(const Dataset& dataset, std::size_t i) {
  if (i < 2) return std::nullopt;
  const auto t0 = dataset.stamp(i - 2), t1 = dataset.stamp(i - 1), t2 = dataset.stamp(i);
  if (!t0 || !t1 || !t2) return std::nullopt;
  return StepTimes{*t1 - *t0, *t2 - *t1};
}

}  // namespace

std::string dataset_label(const Dataset& dataset) {
  const DatasetMetadata& m = dataset.metadata();
  if (!m.path.empty()) return m.path.string();
  return m.name.empty() ? std::string("<dataset>") : m.name;
}

double time_ratio(const Dataset& dataset, std::size_t i) {
  const auto t = step_times(dataset, i);
  if (!t || !(t->before > 0.0 && t->now > 0.0) || !std::isfinite(t->now / t->before)) return 1.0;
  return t->now / t->before;
}

double step_reach(const Dataset& dataset, std::size_t i, double max_acceleration) {
  const auto t = step_times(dataset, i);
  return t ? reachable_departure(t->before, t->now, max_acceleration)
           : std::numeric_limits<double>::infinity();
}

SweepMotion sweep_between(const Dataset& dataset, std::size_t from, std::size_t to, const PointCloud& scan,
                          const Eigen::Isometry3d& motion) {
  if (!scan.has_time() || motion.matrix() == Eigen::Matrix4d::Identity()) return {};
  const auto t0 = dataset.stamp(from), t1 = dataset.stamp(to);
  const double between = t0 && t1 ? *t1 - *t0 : 0.0;
  return {motion, between > 0.0 && std::isfinite(between) ? between : sweep_span(scan)};
}

std::vector<Eigen::Isometry3d> odometry_poses(const Dataset& dataset, const OdometrySettings& s,
                                              std::size_t first, std::size_t count) {
  if (s.guess != OdometryGuess::odometry) return {};
  if (!s.odometry.empty()) {
    if (s.odometry.size() < count)
      throw InputError("odometry settings", "",
                       "the given odometry has " + std::to_string(s.odometry.size()) +
                           " poses, fewer than the " + std::to_string(count) + " scans");
    return {s.odometry.begin(), s.odometry.begin() + static_cast<std::ptrdiff_t>(count)};
  }
  std::vector<Eigen::Isometry3d> poses;
  for (std::size_t k = 0; k < count; ++k) {
    const auto pose = dataset.odometry(first + k);
    if (!pose)
      throw InputError(dataset_label(dataset), "",
                       "scan " + std::to_string(first + k) + " has no odometry (this " +
                           dataset.metadata().format +
                           " dataset has none): the odometry guess needs it; use the constant_velocity "
                           "guess (or identity) instead");
    poses.push_back(*pose);
  }
  return poses;
}

Eigen::Isometry3d start_pose(const Dataset& dataset, const OdometrySettings& s, std::size_t first) {
  if (s.initial_pose) return *s.initial_pose;
  if (const auto truth = dataset.ground_truth(first)) return *truth;
  if (const auto odometry = dataset.odometry(first)) return *odometry;
  return Eigen::Isometry3d::Identity();
}

}  // namespace sextant::odometry_detail
