#pragma once
// Row keys (RunRow::values and ::series names) that more than one family uses.
// A key used by one file only stays a literal there.

namespace sextant::keys {

inline constexpr const char* kConverged = "converged";
inline constexpr const char* kEstimate = "estimate";
inline constexpr const char* kFailedSteps = "failed_steps";
inline constexpr const char* kGroundTruth = "ground_truth";
inline constexpr const char* kIterations = "iterations";
inline constexpr const char* kKummerleRotationDeg = "kummerle_rotation_deg";
inline constexpr const char* kKummerleTranslationM = "kummerle_translation_m";
inline constexpr const char* kNotConverged = "not_converged";
inline constexpr const char* kOdometry = "odometry";
inline constexpr const char* kScans = "scans";
inline constexpr const char* kSeconds = "seconds";
inline constexpr const char* kTrajectory = "trajectory";
inline constexpr const char* kTruth = "truth";
inline constexpr const char* kUpdates = "updates";
inline constexpr const char* kWulfRotationDeg = "wulf_rotation_deg";
inline constexpr const char* kWulfTranslationM = "wulf_translation_m";

}  // namespace sextant::keys
