#pragma once
// Row keys (RunRow::values and ::series names) that several files of the simulation family use.
// A key used by one file only stays a literal there.

#include "kit/row_keys.hpp"  // the keys every family shares

namespace sextant::keys {

inline constexpr const char* kDeadReckoningErrorM = "dead_reckoning_error_m";
inline constexpr const char* kEstX = "est_x";
inline constexpr const char* kEstY = "est_y";
inline constexpr const char* kFinalPositionErrorM = "final_position_error_m";
inline constexpr const char* kHeadingErrorDeg = "heading_error_deg";
inline constexpr const char* kMapX = "map_x";
inline constexpr const char* kMapY = "map_y";
inline constexpr const char* kMeanAlongTrackM = "mean_along_track_m";
inline constexpr const char* kMeanCrossTrackM = "mean_cross_track_m";
inline constexpr const char* kMeanHeadingErrorDeg = "mean_heading_error_deg";
inline constexpr const char* kMeanPositionErrorM = "mean_position_error_m";
inline constexpr const char* kMeanSignedHeadingDeg = "mean_signed_heading_deg";
inline constexpr const char* kPositionErrorM = "position_error_m";
inline constexpr const char* kTruthX = "truth_x";
inline constexpr const char* kTruthY = "truth_y";

}  // namespace sextant::keys
