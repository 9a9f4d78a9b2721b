#pragma once
// The accuracy summary that `sextant odometry` and `sextant eval` print and write: one
// evaluate_trajectory (eval library) per trajectory, so that both commands give the same numbers
// for the same poses by construction.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/eval/trajectory_evaluation.hpp"
#include "sextant/pipeline/json.hpp"

namespace sextant {

/// Accuracy of a trajectory against the ground truth (translations in m, rotations in rad).
struct TrajectoryAccuracy {
  double ate_translation = 0, ate_rotation = 0;  ///< RMS after the alignment (odometry: SE(3) Umeyama)
  double rpe_translation = 0, rpe_rotation = 0;  ///< RMS over the RPE pairs (odometry: consecutive scans)
  std::size_t drift_segments = 0;                ///< KITTI segments (0: path shorter than 100 m)
  double drift_percent = 0, drift_deg_per_100m = 0;
};

TrajectoryAccuracy trajectory_accuracy(const TrajectoryEvaluation& evaluation);
/// SE(3)-aligned ATE, RPE over consecutive poses, KITTI drift; nothing when a metric cannot be
/// computed (a non-finite pose, positions that all coincide), with the reason in `why`: never zeros.
std::optional<TrajectoryAccuracy> trajectory_accuracy(const std::vector<Eigen::Isometry3d>& estimate,
                                                      const std::vector<Eigen::Isometry3d>& truth,
                                                      std::string* why);

/// "ATE 0.123 m / 0.45°, RPE 0.012 m / 0.10° per scan, drift 1.23 % / 0.45°/100 m (N segments)";
/// `rpe_per` names the RPE's step ("scan", "5 frames", "10 m").
std::string accuracy_line(const TrajectoryAccuracy& a, const std::string& rpe_per = "scan");

/// {"ate_m": …, "ate_deg": …, "rpe_m": …, "rpe_deg": …, "drift_segments": …, "drift_percent": …,
/// "drift_deg_per_100m": …} (drift null without segments).
Json accuracy_json(const TrajectoryAccuracy& a);

}  // namespace sextant
