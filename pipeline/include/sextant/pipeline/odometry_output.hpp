#pragma once
// What `sextant odometry` writes and prints: the trajectory as TUM and KITTI files, per-step
// steps.csv, metrics.json and provenance.json (all written atomically), and the accuracy against
// the dataset's ground truth (ATE after SE(3) Umeyama alignment, RPE per step, KITTI drift).
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/dataset.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/pipeline/odometry_request.hpp"
#include "sextant/pipeline/trajectory_accuracy.hpp"

namespace sextant {

/// The poses of scans first … first + count − 1 with the dataset's ground truth, or nothing when
/// any of them lacks it.
std::optional<std::vector<Eigen::Isometry3d>> ground_truth_of(const Dataset& dataset, std::size_t first,
                                                              std::size_t count);
/// Same for the dataset's odometry.
std::optional<std::vector<Eigen::Isometry3d>> odometry_of(const Dataset& dataset, std::size_t first,
                                                          std::size_t count);

/// Writes trajectory.tum and trajectory.kitti.txt (and groundtruth.* when `truth` is given) into
/// `out`. Stamps: the dataset's clock, else the scan index. For a KITTI dataset the KITTI files are
/// in the devkit's camera-0 frame (Tr · T · Tr⁻¹, calib.txt), the TUM files in the Velodyne frame.
void write_trajectories(const std::filesystem::path& out, const Dataset& dataset, std::size_t first,
                        const std::vector<Eigen::Isometry3d>& poses,
                        const std::optional<std::vector<Eigen::Isometry3d>>& truth);

/// steps.csv: one line per registration, the columns of steps_table.hpp.
void write_steps_csv(const std::filesystem::path& file, std::size_t first, const OdometryResult& result,
                     const std::optional<std::vector<Eigen::Isometry3d>>& truth);

/// Steps whose registration did not converge; whose chained motion is not trusted; that the wide
/// basin recovered.
struct OdometryCounts {
  std::size_t not_converged = 0, untrusted = 0, recovered = 0;
  /// Over every scan: the points read and those reading dropped (non-finite, no-return; per scan in
  /// steps.csv), and how many scans dropped any
  ScanLoadReport read;
  std::size_t scans_with_drops = 0;
  /// With ground truth: the steps (indices) whose chained motion is trusted and yet more than the
  /// run's tolerance (OdometryResult::tolerance: a car's 1 m or 5°, less for a slower platform) from the
  /// ground truth's: a wrong registration that passed the checks, or a wrong reference (docs/odometry.md,
  /// "What it prints and writes"). Nothing without ground truth.
  std::optional<std::vector<std::size_t>> trusted_off_reference;
};

/// The counts of `result` (without trusted_off_reference, which needs the ground truth).
OdometryCounts odometry_counts(const OdometryResult& result);

/// "6499 of 25996 points dropped (6499 non-finite, 0 no-return), in 1 of 2 scans (per scan:
/// steps.csv)" for the console (dropped_points_note over the run); empty when none was.
std::string dropped_points_line(const OdometryCounts& counts, std::size_t scans);

/// What a run does with the scans' per-point times, from scan `first` of `dataset` (read here), for the
/// run's header: "constant velocity, points carry time (sweep 0.100 s)", "off: the points carry no
/// time", or off as `face` spells the switch ("off (--no-deskew) …" / "off (deskew=False) …").
std::string deskew_line(const OdometrySettings& settings, const Dataset& dataset, std::size_t first,
                        Face face);

/// "constant_velocity", or "off" (deskew turned off), for provenance.json and Python.
std::string deskew_scheme(const OdometrySettings& settings);

/// The trusted steps of `result` more than `tolerance`'s ambiguity distance from `truth`'s relative
/// motions (OdometryCounts::trusted_off_reference).
std::vector<std::size_t> trusted_steps_off_reference(const OdometryResult& result,
                                                     const std::vector<Eigen::Isometry3d>& truth,
                                                     const QualitySettings& tolerance);

/// "3 trusted steps lie more than 1 m or 5° from the reference's motion (scans 107→108, 108→109,
/// 110→111): ..." for the console; empty when there are none.
std::string off_reference_warning(const std::vector<std::size_t>& steps, std::size_t first,
                                  const QualitySettings& tolerance);

/// With --loop-closure: what closing the loops did, and the chained trajectory's accuracy before.
struct LoopClosureSummary {
  std::string source;
  std::size_t candidates = 0, accepted = 0;
  double seconds = 0.0, descriptor_seconds = 0.0;
  std::optional<TrajectoryAccuracy> chained;
  /// Per source, with ground truth: "proximity" / "descriptor" → candidates, precision, recall,
  /// accepted, accepted_wrong (odometry_loop_closure.hpp).
  std::vector<std::pair<std::string, std::vector<std::pair<std::string, double>>>> sources;
};

/// metrics.json: the step counts, the estimate's accuracy and, when the dataset has odometry, the
/// odometry's; with loop closure, a "loop_closure" map (the estimate is then the loop-closed one).
void write_metrics_json(const std::filesystem::path& file, const std::optional<TrajectoryAccuracy>& estimate,
                        const std::optional<TrajectoryAccuracy>& odometry, std::size_t scans,
                        const OdometryCounts& counts, double seconds,
                        const std::optional<LoopClosureSummary>& loops = std::nullopt);

}  // namespace sextant
