#pragma once
// One plane-SLAM run over a scan sequence of the synthetic campus, recorded per scan (the
// `plane_slam` and `pose_graph` kinds). The SLAM driver is the filters library's: run_slam
// (filters/slam_runner.hpp) for true landmarks, run_plane_slam (filters/plane_slam.hpp) for
// extracted ones; this file turns the campus into their input and records through their per-step
// callbacks (Filter::diagnostics() for the information filters' Ω):
//   true landmarks — per scan, every true plane with ≥ min_points points on it is observed from
//     the true pose, z = h(x_true, m) + N(0, R) (eq. 4.64; normal renormalised), and associated
//     by its true id; an id seen for the first time is augmented (eqs. 4.57–4.58);
//   extracted landmarks — PlaneSlam (filters/plane_slam.hpp): extraction, semantic association
//     and χ² gate on the scan itself.
// Both predict with the odometry increment (eq. 4.72) — or, extracted landmarks with a method's
// motion: fbmlndt, with the FbML-NDT relative pose on the shared extraction (hybrid SLAM, E21,
// kit/fbmlndt_motion.hpp) — and record per scan the pose, its
// covariance (Filter::joint_covariance: exact for the moment filters, SEIF's Markov-blanket
// approximation), the motion- and measurement-update times, and — for information filters —
// the block pattern of Ω when the map reaches the sizes asked for.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kit/plane_slam_params.hpp"
#include "sextant/core/point_cloud.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/filters/filter.hpp"
#include "sextant/synth/campus.hpp"

namespace sextant {

/// What every run of an experiment shares (read-only while runs execute).
struct CampusScans {
  const synth::Campus* campus = nullptr;
  std::vector<std::vector<synth::LandmarkVisibility>> visible;  ///< true landmarks: per scan
  std::vector<PointCloud> clouds;                               ///< extracted landmarks: per scan
};

struct RecordedStep {
  Vector6d pose = Vector6d::Zero();
  Matrix6d covariance = Matrix6d::Zero();  ///< pose block (NaN when it could not be read)
  double motion_seconds = 0.0;             ///< predict
  double measurement_seconds = 0.0;        ///< update + augmentation
  double extraction_seconds = 0.0;         ///< extracted landmarks: plane extraction
  double association_seconds = 0.0;        ///< extracted landmarks: association + χ² gate
  double registration_seconds = 0.0;       ///< motion: fbmlndt: the registration (0 otherwise)
  int matched_motion = -1;                 ///< motion: fbmlndt: 1 matcher's increment, 0 odometry's
  std::size_t map_size = 0;
  std::size_t updated = 0, augmented = 0, gated = 0;
  bool ok = true;  ///< every filter step of the scan reported kOk
  /// params.marginal_nees: the pose block of the exact marginal (SEIF: (Ω⁻¹)_vv, not its
  /// Markov-blanket covariance; the other filters: `covariance`).
  bool has_marginal = false;
  Matrix6d marginal = Matrix6d::Zero();
  double active = -1.0;  ///< information filters: landmarks linked to the pose (−1: other filters)
};

/// Ω's block pattern: variable 0 = pose (6 rows), variable k = landmark k−1 (4 rows).
struct InformationPattern {
  std::size_t scan = 0;       ///< after this scan
  std::size_t landmarks = 0;  ///< map size then
  std::vector<double> links;  ///< flat (i, j) pairs, i < j, of linked variables
};

struct RecordedRun {
  std::vector<RecordedStep> steps;
  std::vector<Pose6> odometry;  ///< dead reckoning from the true start with the filters' increments
  FilterSummary summary;
  std::vector<Eigen::Vector4d> map;  ///< final landmarks (n, d)
  std::vector<int> map_truth;        ///< true landmark id per map landmark (−1: unknown)
  std::vector<InformationPattern> information;
  std::size_t relocations = 0, skipped_relocations = 0;  ///< ESEIF
};

/// Runs `scans` scans. `seed` draws the resampled odometry and the observation noise; `method`
/// chooses the motion source (default: the odometry).
RecordedRun record_plane_slam(const CampusScans& data, const PlaneSlamParams& params,
                              const PlaneSlamSettings& settings, std::size_t scans, std::uint64_t seed,
                              const PlaneSlamMethod& method = {});

}  // namespace sextant
