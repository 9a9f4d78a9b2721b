#pragma once
// Row keys (RunRow::values and ::series names) that several files of the plane_features family use.
// A key used by one file only stays a literal there.

#include "kit/row_keys.hpp"  // the keys every family shares

namespace sextant::keys {

inline constexpr const char* kAssociationPossible = "association_possible";
inline constexpr const char* kCellPlanes = "cell_planes";
inline constexpr const char* kHorizontalRemoved = "horizontal_removed";
inline constexpr const char* kLandmarks = "landmarks";
inline constexpr const char* kMergedPlanes = "merged_planes";
inline constexpr const char* kPoints = "points";
inline constexpr const char* kPoseX = "pose_x";
inline constexpr const char* kPoseY = "pose_y";
inline constexpr const char* kRecalledTruePlanes = "recalled_true_planes";
inline constexpr const char* kTooSmallRemoved = "too_small_removed";
inline constexpr const char* kTruePositives = "true_positives";
inline constexpr const char* kTrueTranslationM = "true_translation_m";
inline constexpr const char* kTrueYawDeg = "true_yaw_deg";
inline constexpr const char* kVisibleTruePlanes = "visible_true_planes";

}  // namespace sextant::keys
