#pragma once
// The `plane_slam` kind's view of an experiment config: plane SLAM over
// the first `scans` scans of the campus with every filter of the catalogue (filter_spec.hpp).
//
//   methods:
//     - {name: ekf, filter: ekf}                       # a filter of filter_spec.hpp (+ filter_settings)
//     - {name: eif, filter: eif, scans: 40}            # a method may stop early (E17's EIF image)
//     - {name: ekf_fbmlndt, filter: ekf, motion: fbmlndt, matcher: {solver: lm}}
//                                                      # motion: odometry (default) | fbmlndt: the
//                                                      # FbML-NDT relative pose predicts (hybrid SLAM,
//                                                      # E21; needs landmarks: extracted); matcher: the
//                                                      # mlndt keys of its registration
//     - {name: fastslam_50_x, filter: fastslam2, landmarks: extracted}
//                                                      # the method's own landmark source (default:
//                                                      # params.landmarks): E23's extracted rows
//     - {name: ekf_t, filter: ekf, odometry: {model: student_t, student_t_dof: 3}}
//                                                      # the method's own odometry model (the
//                                                      # campus' odometry keys): its odometry is
//                                                      # drawn per run from it (E23's heavy tails)
//   sweep:
//     p0_scale: [1, 1000, 1.0e6]                       # optional: overrides slam.p0_scale
//   params:
//     landmarks: true          # true: the campus' true planes seen from the true pose + N(0, R),
//                              # true association; extracted: extraction + semantic association
//     scans: 211               # the first N scans (≤ the campus' scans)
//     first: 17                # optional: start at this scan instead (the run begins at its true pose)
//     min_points: 300          # true: a plane is observed when the scan has ≥ this many points on it
//     odometry: resample       # campus: the dataset's odometry; resample: drawn per run from the
//                              # run seed with the campus' odometry model (Monte Carlo repetitions)
//     slam: {sigma_xy: 0.5, …} # PlaneSlamSettings keys (filters/plane_slam.hpp) except filter
//     report: accuracy         # accuracy | seif | benchmark | eseif | hybrid | fastslam
//     marginal_nees: false     # also the NEES from the exact marginal of SEIF's Ω (nees_marginal)
//     information_at: [118, 0] # information filters: block pattern of Ω when the map first
//                              # reaches these sizes (0: after the last scan)
//     nees_probability: 0.99   # a step is inconsistent when NEES > χ²₆ quantile of this
//     failures_are_results: false  # true (E13's P0 study): a filter that fails on most of its steps
//                              # is the measured outcome, an ok row with its failure counts
//                              # (ended_by_failures = 1), not a failed run (slam_run_failure)
//     compare_scans: 120      # also compute the metrics over the first N scans (prefix_… values), so
//                              # filters run over different lengths compare on a common prefix
//     claims: [...]            # the thesis' comparative claims, decided on our rows (claims.hpp)
//     hybrid: {noise_scale: 1, alarm_translation: 0.6, alarm_rotation_deg: 3, max_extra_cost: 0.5,
//              block: 20}
//                              # motion: fbmlndt: Σ = noise_scale · H⁻¹; the odometry's increment is
//                              # used instead when the matcher and the odometry disagree beyond the
//                              # alarm thresholds (as Table 3.3's KF does), or the registration failed;
//                              # report: hybrid: the cost band of the claim and the bootstrap block
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "sextant/experiments/experiment_config.hpp"
#include "sextant/filters/filter_spec.hpp"
#include "sextant/filters/plane_slam.hpp"
#include "sextant/synth/settings.hpp"

namespace sextant {

enum class LandmarkSource { kTrue, kExtracted };
enum class OdometrySource { kCampus, kResample };
enum class MotionSource { kOdometry, kFbmlndt };

/// Hybrid SLAM: how the FbML-NDT relative pose becomes the motion prediction.
struct HybridParams {
  double noise_scale = 1.0;           ///< Σ = noise_scale · H⁻¹ (eq. 3.50) [-]
  double alarm_translation = 0.6;     ///< ‖δt_matcher − δt_odometry‖ above this: odometry used [m]
  double alarm_rotation = 0.0523599;  ///< max |δo_matcher − δo_odometry| above this: odometry used [rad]
  double max_extra_cost = 0.5;  ///< report: "little extra cost" = registration ≤ this share of the rest [-]
  std::size_t block = 20;       ///< report: block length of the moving-block bootstrap over scans
};

struct PlaneSlamParams {
  LandmarkSource landmarks = LandmarkSource::kTrue;
  std::size_t scans = 0;  ///< 0: every scan of the campus (from `first`)
  std::size_t first = 0;  ///< the campus scan the run starts at (scan 0 of every series)
  std::size_t min_points = 300;
  OdometrySource odometry = OdometrySource::kCampus;
  /// `slam:` the PlaneSlamSettings keys but `filter` / `filter_settings` (each method's, plane_slam_settings)
  PlaneSlamSettings slam;
  std::string report = "accuracy";  ///< the plane_slam kind's layout (checked against its table)
  std::vector<std::size_t> information_at;
  double nees_probability = 0.99;
  bool marginal_nees = false;      ///< also record the NEES from the exact marginal (SEIF: of Ω)
  std::size_t ellipse_every = 10;  ///< report: one pose ellipse every N scans
  // E19: loop closures on the route and spikes of the relative errors (sequence_analysis.hpp).
  double revisit_radius = 12.0;       ///< [m]
  std::size_t revisit_gap = 40;       ///< scans
  double spike_threshold = 5.0;       ///< robust z-score
  std::size_t spike_window = 10;      ///< a spike within ±N scans of a revisit start is "at a loop closure"
  bool failures_are_results = false;  ///< a filter failing on most steps is an ok row, not a failed run
  std::size_t compare_scans = 0;      ///< > 0: the metrics also over the first N scans ("prefix_…" values)
  YAML::Node claims;                  ///< sequence or null
  HybridParams hybrid;

  bool valid(std::string* why) const;
};

struct PlaneSlamMethod {
  std::string name;
  FilterSpec filter;      ///< `filter:` and `filter_settings:`
  std::size_t scans = 0;  ///< 0: params.scans
  MotionSource motion = MotionSource::kOdometry;
  YAML::Node matcher;  ///< motion: fbmlndt: mlndt settings of the registration (may be null)
  /// `odometry:` the method's own odometry model (the campus' keys, e.g. {model: student_t}): the
  /// odometry is then drawn from it per run (as odometry: resample), not from the campus' model.
  std::optional<synth::OdometrySettings> odometry;
  /// `landmarks:` the method's own landmark source (true | extracted), else params.landmarks.
  std::optional<LandmarkSource> landmarks;
};

/// The landmark source of one method: its own, else the experiment's.
inline LandmarkSource landmark_source(const PlaneSlamParams& params, const PlaneSlamMethod& method) {
  return method.landmarks ? *method.landmarks : params.landmarks;
}

/// The one sweep axis the kind understands: the scale of the initial covariance P0.
inline constexpr const char* kP0ScaleAxis = "p0_scale";

PlaneSlamParams read_plane_slam_params(const ExperimentConfig& config);
PlaneSlamMethod read_plane_slam_method(const YAML::Node& node, const std::string& file);
/// The filters' settings of one method at one p0_scale (NaN: the config's): validated, InputError.
PlaneSlamSettings plane_slam_settings(const PlaneSlamParams& params, const PlaneSlamMethod& method,
                                      double p0_scale, const std::string& file);
/// Checks the sweep axes (only p0_scale, positive numbers).
void check_plane_slam_sweep(const ExperimentConfig& config);

}  // namespace sextant
