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

}  // namespace sextant::keys
