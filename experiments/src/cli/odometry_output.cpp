#include "odometry_output.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "sextant/core/atomic_file.hpp"
#include "sextant/core/io/kitti.hpp"
#include "sextant/core/io/trajectory_io.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/trajectory_metrics.hpp"
#include "sextant/experiments/json.hpp"
#include "sextant/matchers/registration_quality.hpp"

namespace sextant::cli {
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

std::string csv_free_text(std::string text) {
  for (char& c : text)
    if (c == ',' || c == '"') c = ';';
  return text;
}

void write_steps_csv(const std::filesystem::path& file, std::size_t first, const OdometryResult& result,
                     const std::optional<std::vector<Eigen::Isometry3d>>& truth) {
  std::ostringstream out;
  out << "step,from_scan,to_scan,x_m,y_m,z_m,roll_deg,pitch_deg,yaw_deg,guess_x_m,guess_y_m,guess_yaw_deg,"
         "converged,iterations,score,matched_points,reference_points,seconds,error_m,error_deg,status,"
         "trust,first_trust,recovery,overlap,constraint_ratio,fit_ratio,trust_reason,fallback,"
         "first_x_m,first_y_m,first_z_m,first_roll_deg,first_pitch_deg,first_yaw_deg,first_error_m,"
         "first_error_deg\n";
  out << std::setprecision(9);
  for (std::size_t i = 0; i < result.steps.size(); ++i) {
    const OdometryStep& s = result.steps[i];
    const Pose6 p = to_pose6(s.relative);
    const Pose6 g = to_pose6(s.guess);
    out << i << "," << first + i << "," << first + i + 1 << "," << p.x << "," << p.y << "," << p.z << ","
        << p.alpha * kDegPerRad << "," << p.beta * kDegPerRad << "," << p.gamma * kDegPerRad << "," << g.x
        << "," << g.y << "," << g.gamma * kDegPerRad << "," << (s.converged ? 1 : 0) << "," << s.iterations
        << "," << s.score << "," << s.matched_points << "," << s.reference_points << "," << s.seconds << ",";
    const auto write_error = [&](const Eigen::Isometry3d& motion) {
      if (!truth) return void(out << ",");
      const Eigen::Isometry3d E = relative(relative((*truth)[i], (*truth)[i + 1]), motion);
      out << translation_norm(E) << "," << rotation_angle(E) * kDegPerRad;
    };
    write_error(s.relative);
    out << "," << s.status << "," << to_string(s.quality.trust) << "," << to_string(s.first_trust) << ","
        << s.recovery << "," << s.quality.overlap << "," << s.quality.constraint_ratio << ","
        << s.quality.fit_ratio << "," << csv_free_text(s.quality.reason) << "," << csv_free_text(s.fallback);
    // The first registration's own pose (what the scans said before any recovery replaced it).
    const Pose6 f = to_pose6(s.first_relative);
    out << "," << f.x << "," << f.y << "," << f.z << "," << f.alpha * kDegPerRad << "," << f.beta * kDegPerRad
        << "," << f.gamma * kDegPerRad << ",";
    write_error(s.first_relative);
    out << "\n";
  }
  write_file_atomically(file, out.str());
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

void write_metrics_json(const std::filesystem::path& file, const std::optional<TrajectoryAccuracy>& estimate,
                        const std::optional<TrajectoryAccuracy>& odometry, std::size_t scans,
                        const OdometryCounts& counts, double seconds,
                        const std::optional<LoopClosureSummary>& loops) {
  Json metrics = {
      {"scans", scans},
      {"not_converged", counts.not_converged},
      {"untrusted", counts.untrusted},
      {"recovered", counts.recovered},
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

}  // namespace sextant::cli
