#pragma once
// Row keys (RunRow::values and ::series names) that several files of the sequence family use.
// A key used by one file only stays a literal there.

#include "kit/row_keys.hpp"  // the keys every family shares

namespace sextant::keys {

inline constexpr const char* kAlarms = "alarms";
inline constexpr const char* kCovarianceXyz = "covariance_xyz";
inline constexpr const char* kEndXyEstimate = "end_xy_estimate";
inline constexpr const char* kEndXyOdometry = "end_xy_odometry";
inline constexpr const char* kMatcher = "matcher";
inline constexpr const char* kMeanXyEstimate = "mean_xy_estimate";
inline constexpr const char* kMeanXyOdometry = "mean_xy_odometry";
// The KF's consistency (kind.cpp's consistency(), kalman.cpp's table): the registrations' NEES scale, and
// the relative fusion's share of scans inside its 95 % ellipsoid and mean horizontal error, with R = H⁻¹
// and with R scaled by that NEES.
inline constexpr const char* kRegistrationNeesScale = "registration_nees_scale";
inline constexpr const char* kRegistrationTail = "registration_beyond_99";  // share beyond the scaled 99 %
inline constexpr const char* kRegistrationBias = "registration_bias";       // largest |mean| / σ of an axis
inline constexpr const char* kRelativeInside95 = "relative_kf_inside_95";
inline constexpr const char* kRelativeMeanXy = "relative_kf_mean_xy";
inline constexpr const char* kScaledInside95 = "scaled_relative_kf_inside_95";
inline constexpr const char* kScaledMeanXy = "scaled_relative_kf_mean_xy";

}  // namespace sextant::keys
