#pragma once
// The per-step table of an odometry run, one row per registration, written once for every face:
// `sextant odometry`'s steps.csv (write_steps_csv) and sextant.odometry()'s OdometryRun.steps (one NumPy
// array per column). The columns, in order: step, from_scan, to_scan, the relative pose (x_m … yaw_deg;
// roll/pitch/yaw are α/β/γ, eq. 3.8), the guess (guess_x_m, guess_y_m, guess_yaw_deg), converged,
// iterations, score, matched_points, reference_points, dropped_non_finite and dropped_no_return (the
// points reading to_scan's file dropped), seconds, the error against the ground truth
// (error_m, error_deg; none without), status, trust, first_trust, recovery, overlap, constraint_ratio,
// fit_ratio, trust_reason, fallback, then the first registration's own pose and error before any
// recovery replaced it (first_x_m … first_yaw_deg, first_error_m, first_error_deg).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/odometry/odometry.hpp"

namespace sextant {

/// One column: its name and its values, of one kind.
struct StepsColumn {
  enum class Kind { integer, real, flag, text };
  std::string name;
  Kind kind = Kind::real;
  std::vector<long long> integers;  ///< Kind::integer
  std::vector<double> reals;        ///< Kind::real
  /// No values: the errors without ground truth (reals all NaN; empty fields in the CSV)
  bool missing = false;
  std::vector<bool> flags;         ///< Kind::flag
  std::vector<std::string> texts;  ///< Kind::text
};

struct StepsTable {
  std::vector<StepsColumn> columns;
  std::size_t rows = 0;
};

/// The table of `result`'s steps (scans first … first + steps), with errors against `truth` (the
/// poses of the same scans) when given.
StepsTable steps_table(const OdometryResult& result, std::size_t first,
                       const std::optional<std::vector<Eigen::Isometry3d>>& truth);

/// The table as CSV: a header of the column names, then one line per row; reals with 9 significant
/// digits (empty fields for a missing column), flags 1 / 0, texts with commas and quotes replaced by ';'.
std::string steps_csv(const StepsTable& table);

/// Free text in a CSV field: no commas or quotes inside.
std::string csv_free_text(std::string text);

}  // namespace sextant
