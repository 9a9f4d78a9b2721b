#include "sextant/pipeline/odometry_output.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "sextant/core/atomic_file.hpp"
#include "sextant/core/io/kitti.hpp"
#include "sextant/core/io/trajectory_io.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/trajectory_metrics.hpp"
#include "sextant/matchers/registration_quality.hpp"
#include "sextant/pipeline/json.hpp"
#include "sextant/pipeline/steps_table.hpp"

namespace sextant {
namespace {

Trajectory stamped(const Dataset& dataset, std::size_t first, const std::vector<Eigen::Isometry3d>& poses) {
  Trajectory t;
  for (std::size_t i = 0; i < poses.size(); ++i)
    t.push_back({dataset.stamp(first + i).value_or(static_cast<double>(first + i)), poses[i]});
  return t;
}

/// KITTI datasets: the devkit's camera-0 frame, Tr · T · Tr⁻¹ (the inverse of kitti_velodyne_poses).
Trajectory kitti_frame(const Dataset& dataset, Trajectory t) {
  if (dataset.metadata().format != "kitti") return t;
  const auto calib = dataset.metadata().path / "calib.txt";
  if (!std::filesystem::exists(calib)) return t;
  const Eigen::Isometry3d Tr = read_kitti_calib_tr(calib);
  for (auto& p : t) p.pose = Tr * p.pose * Tr.inverse();
  return t;
}

std::optional<std::vector<Eigen::Isometry3d>> poses_of_dataset(
    std::size_t first, std::size_t count,
    const std::function<std::optional<Eigen::Isometry3d>(std::size_t)>& pose) {
  std::vector<Eigen::Isometry3d> poses;
  for (std::size_t i = first; i < first + count; ++i) {
    const auto p = pose(i);
    if (!p) return std::nullopt;
    poses.push_back(*p);
  }
  return poses;
}

}  // namespace

std::optional<std::vector<Eigen::Isometry3d>> ground_truth_of(const Dataset& dataset, std::size_t first,
                                                              std::size_t count) {
  return poses_of_dataset(first, count, [&](std::size_t i) { return dataset.ground_truth(i); });
}

std::optional<std::vector<Eigen::Isometry3d>> odometry_of(const Dataset& dataset, std::size_t first,
                                                          std::size_t count) {
  return poses_of_dataset(first, count, [&](std::size_t i) { return dataset.odometry(i); });
}

void write_trajectories(const std::filesystem::path& out, const Dataset& dataset, std::size_t first,
                        const std::vector<Eigen::Isometry3d>& poses,
                        const std::optional<std::vector<Eigen::Isometry3d>>& truth) {
  const Trajectory estimate = stamped(dataset, first, poses);
  write_tum_trajectory(out / "trajectory.tum", estimate);
  write_kitti_trajectory(out / "trajectory.kitti.txt", kitti_frame(dataset, estimate));
  if (!truth) return;
  const Trajectory reference = stamped(dataset, first, *truth);
  write_tum_trajectory(out / "groundtruth.tum", reference);
  write_kitti_trajectory(out / "groundtruth.kitti.txt", kitti_frame(dataset, reference));
}

void write_steps_csv(const std::filesystem::path& file, std::size_t first, const OdometryResult& result,
                     const std::optional<std::vector<Eigen::Isometry3d>>& truth) {
  write_file_atomically(file, steps_csv(steps_table(result, first, truth)));
}

std::string deskew_scheme(const OdometrySettings& settings) {
  return settings.deskew ? "constant_velocity" : "off";
}

std::string deskew_line(const OdometrySettings& settings, const Dataset& dataset, std::size_t first,
                        Face face) {
  const PointCloud scan = load_sequence_scan(dataset, first, settings.min_range);
  const std::string off = "off (" + (face == Face::cli ? std::string("--no-deskew") : "deskew=False") + ")";
  if (!scan.has_time()) return settings.deskew ? "off: the points carry no time" : off;
  std::ostringstream sweep;
  sweep << std::fixed << std::setprecision(3) << sweep_span(scan) << " s";
  if (!settings.deskew)
    return off + ": the points carry time (a sweep of " + sweep.str() +
           ") but are registered where they were measured";
  return "constant velocity, points carry time (a sweep of " + sweep.str() + ")";
}

std::vector<std::size_t> trusted_steps_off_reference(const OdometryResult& result,
                                                     const std::vector<Eigen::Isometry3d>& truth,
                                                     const QualitySettings& tolerance) {
  std::vector<std::size_t> off;
  for (std::size_t i = 0; i < result.steps.size() && i + 1 < truth.size(); ++i)
    if (result.steps[i].trusted() &&
        far_apart(result.steps[i].relative, relative(truth[i], truth[i + 1]), tolerance))
      off.push_back(i);
  return off;
}

std::string off_reference_warning(const std::vector<std::size_t>& steps, std::size_t first,
                                  const QualitySettings& tolerance) {
  if (steps.empty()) return "";
  std::ostringstream out;
  out << steps.size() << " trusted step" << (steps.size() == 1 ? " lies" : "s lie") << " more than "
      << std::setprecision(2) << tolerance.ambiguity_metres << " m or " << tolerance.ambiguity_degrees
      << "° from the reference's motion (scans ";
  constexpr std::size_t kListed = 8;
  for (std::size_t k = 0; k < std::min(steps.size(), kListed); ++k)
    out << (k ? ", " : "") << first + steps[k] << "→" << first + steps[k] + 1;
  if (steps.size() > kListed) out << ", …";
  out << "): the reference or " << (steps.size() == 1 ? "this registration is" : "these registrations are")
      << " wrong there, and the accuracy includes them";
  return out.str();
}

OdometryCounts odometry_counts(const OdometryResult& result) {
  OdometryCounts counts;
  for (const auto& step : result.steps) counts.not_converged += step.converged ? 0 : 1;
  counts.untrusted = result.untrusted();
  counts.recovered = result.recovered();
  counts.read = result.dropped_total();
  for (const ScanLoadReport& load : result.loads) counts.scans_with_drops += load.dropped() > 0 ? 1 : 0;
  return counts;
}

std::string dropped_points_line(const OdometryCounts& counts, std::size_t scans) {
  const std::string dropped = dropped_points_note(counts.read);
  if (dropped.empty()) return "";
  return dropped + ", in " + std::to_string(counts.scans_with_drops) + " of " + std::to_string(scans) +
         " scans (per scan: steps.csv)";
}

void write_metrics_json(const std::filesystem::path& file, const std::optional<TrajectoryAccuracy>& estimate,
                        const std::optional<TrajectoryAccuracy>& odometry, std::size_t scans,
                        const OdometryCounts& counts, double seconds,
                        const std::optional<LoopClosureSummary>& loops) {
  Json metrics = {
      {"scans", scans},
      {"not_converged", counts.not_converged},
      {"untrusted", counts.untrusted},
      {"recovered", counts.recovered},
      {"points_read", counts.read.points_read},
      {"dropped_non_finite", counts.read.non_finite_dropped},
      {"dropped_no_return", counts.read.no_return_dropped},
      {"trusted_off_reference", counts.trusted_off_reference ? Json(*counts.trusted_off_reference) : Json()},
      {"seconds", json_value(seconds)},
      {"estimate", estimate ? accuracy_json(*estimate) : Json()},
      {"odometry", odometry ? accuracy_json(*odometry) : Json()}};
  if (loops)
    metrics["loop_closure"] = {{"source", loops->source},
                               {"candidates", loops->candidates},
                               {"accepted", loops->accepted},
                               {"seconds", json_value(loops->seconds)},
                               {"descriptor_seconds", json_value(loops->descriptor_seconds)},
                               {"chained", loops->chained ? accuracy_json(*loops->chained) : Json()}};
  if (loops)
    for (const auto& [source, numbers] : loops->sources) {
      Json& entry = metrics["loop_closure"]["sources"][source];
      for (const auto& [key, value] : numbers) entry[key] = json_value(value);
    }
  write_file_atomically(file, json_line(metrics) + "\n");
}

}  // namespace sextant
