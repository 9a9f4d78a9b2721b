#pragma once
// Row keys (RunRow::values and ::series names) that several files of the plane_slam family use.
// A key used by one file only stays a literal there.

#include "kit/row_keys.hpp"  // the keys every family shares

namespace sextant::keys {

inline constexpr const char* kAssociationMs = "association_ms";
inline constexpr const char* kCholeskyFailures = "cholesky_failures";
inline constexpr const char* kEndedByFailures = "ended_by_failures";
inline constexpr const char* kErrorM = "error_m";
inline constexpr const char* kExtractionMs = "extraction_ms";
inline constexpr const char* kFirstFailureScan = "first_failure_scan";
inline constexpr const char* kMapSegments = "map_segments";
inline constexpr const char* kMapSize = "map_size";
inline constexpr const char* kMeasurementMs = "measurement_ms";
inline constexpr const char* kMotionMatchedFraction = "motion_matched_fraction";
inline constexpr const char* kMotionMs = "motion_ms";
inline constexpr const char* kNees = "nees";
inline constexpr const char* kNeesBound = "nees_bound";
inline constexpr const char* kNeesMarginal = "nees_marginal";
inline constexpr const char* kNotPositiveDefinite = "not_positive_definite";
inline constexpr const char* kOdometryErrorM = "odometry_error_m";
inline constexpr const char* kOdometryFinalErrorM = "odometry_final_error_m";
inline constexpr const char* kOdometryMeanErrorM = "odometry_mean_error_m";
inline constexpr const char* kOdometryRotationErrorDeg = "odometry_rotation_error_deg";
inline constexpr const char* kPositionCovariance = "position_covariance";
inline constexpr const char* kRegistrationMs = "registration_ms";
inline constexpr const char* kRotationErrorDeg = "rotation_error_deg";
inline constexpr const char* kStepMs = "step_ms";

}  // namespace sextant::keys
