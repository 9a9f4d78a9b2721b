#pragma once
// Accuracy of pairwise registrations, as the thesis' tables 5.1–5.9 report it: the relative
// transform error E = T_gt⁻¹ · T_est per parameter (tx, ty, tz in cm; α, β, γ in degrees, eq. (3.8)
// angles via to_pose6), its norms, the success rate under configurable thresholds, and iteration,
// time and matched-point statistics.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/pose.hpp"
#include "sextant/eval/statistics.hpp"

namespace sextant {

/// Which axis names the per-parameter errors use.
enum class AxisConvention {
  internal,  ///< ours: x forward, y left, z up; α, β, γ about x, y, z
  uos,       ///< the thesis' tables: x_uos = −y, y_uos = z, z_uos = x (left-handed, y up)
};

/// The relative-transform error of one registration.
struct RegistrationError {
  /// tx, ty, tz [cm], α, β, γ [deg] of E = T_gt⁻¹ · T_est in the chosen axis convention.
  std::array<double, 6> parameters{};
  double translation_cm = 0.0;  ///< ‖t(E)‖ [cm]
  double rotation_deg = 0.0;    ///< rotation angle of E [deg], in [0, 180]
  bool finite = true;           ///< false when the estimate had NaN/inf entries (then all fields are NaN)
};

/// Names of the six parameters for table headers ("tx", "ty", "tz", "α", "β", "γ").
const std::array<std::string, 6>& parameter_names();

/// E = T_gt⁻¹ · T_est, split per parameter and as norms.
RegistrationError registration_error(const Eigen::Isometry3d& estimate, const Eigen::Isometry3d& ground_truth,
                                     AxisConvention axes = AxisConvention::internal);

/// A rigid transform expressed in the uos axes (core's internal_pose_to_uos, kept in metres):
/// M · T · Mᵀ with M's rows x_uos = −y, y_uos = z, z_uos = x. Because M is a reflection, a positive
/// yaw about our z becomes a negative β_uos (the heading about y_uos) — exactly what a uos `.pose`
/// file written by core's uos writer holds.
Eigen::Isometry3d to_uos_axes(const Eigen::Isometry3d& T);
/// Maps a point/vector of ours to uos axes (same units): (−y, z, x).
Eigen::Vector3d to_uos_axes(const Eigen::Vector3d& v);

/// When is a registration a success? The thesis uses translation < 50 cm (tables 5.1–5.6) and
/// translation < 200 cm with rotation < 10° (table 5.9).
struct SuccessCriterion {
  double max_translation_cm = 50.0;  ///< success needs ‖t(E)‖ < this [cm]; +inf disables
  double max_rotation_deg = 1e300;   ///< success needs angle(E) < this [deg]; huge disables
  bool require_converged = false;    ///< also require the matcher to report convergence

  bool valid(std::string* why) const;
  bool succeeded(const RegistrationError& error, bool converged) const;
};

/// The thesis' two criteria by name: "translation_50cm" and "translation_200cm_rotation_10deg".
SuccessCriterion thesis_success_criterion(const std::string& name);

/// One registration as the metrics need it (the runner fills it from a RegistrationResult).
struct RegistrationSample {
  Eigen::Isometry3d estimate = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d ground_truth = Eigen::Isometry3d::Identity();
  bool converged = true;
  int iterations = 0;
  double seconds = 0.0;            ///< wall time of the registration [s]
  std::size_t matched_points = 0;  ///< points that found a cell / correspondence
  std::size_t total_points = 0;    ///< points that were tried (0: matched percentage unknown)
};

struct RegistrationStatsSettings {
  AxisConvention axes = AxisConvention::internal;
  SuccessCriterion success;
  /// Error statistics over the successful registrations only (tables 5.5 and 5.6 exclude the
  /// failures); iterations, time and matched points always cover every sample.
  bool errors_of_successes_only = false;

  bool valid(std::string* why) const;
};

/// Tables 5.1–5.6 and 5.9 in one struct.
struct RegistrationStats {
  std::size_t count = 0;                  ///< samples given
  std::size_t successes = 0;              ///< samples meeting the criterion
  double success_rate = 0.0;              ///< successes / count, in [0, 1] (0 when count = 0)
  std::array<SampleStats, 6> parameters;  ///< tx, ty, tz [cm], α, β, γ [deg] of E
  SampleStats translation_cm;             ///< ‖t(E)‖ [cm]
  SampleStats rotation_deg;               ///< angle(E) [deg]
  SampleStats iterations;
  SampleStats seconds;
  SampleStats matched_percent;            ///< 100 · matched / total over samples with total > 0
  std::vector<RegistrationError> errors;  ///< one per sample, in input order
  std::vector<bool> success;              ///< one per sample
};

RegistrationStats registration_stats(const std::vector<RegistrationSample>& samples,
                                     const RegistrationStatsSettings& settings = {});

}  // namespace sextant
