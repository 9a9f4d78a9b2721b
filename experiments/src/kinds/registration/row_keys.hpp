#pragma once
// Row keys (RunRow::values and ::series names) that several files of the registration family use.
// A key used by one file only stays a literal there.

#include "kit/row_keys.hpp"  // the keys every family shares

namespace sextant::keys {

inline constexpr const char* kAdaptivePair = "adaptive_pair";
inline constexpr const char* kAdaptiveRuleFailure = "adaptive_rule_failure";
inline constexpr const char* kAdaptiveStartLayer = "adaptive_start_layer";
inline constexpr const char* kCellEdgeM = "cell_edge_m";
inline constexpr const char* kInitial = "initial";
inline constexpr const char* kInitialTranslationCm = "initial_translation_cm";
inline constexpr const char* kInputPoints = "input_points";
inline constexpr const char* kKeptFraction = "kept_fraction";
inline constexpr const char* kLayer = "layer";
inline constexpr const char* kMatchedPercent = "matched_percent";
inline constexpr const char* kReferenceScan = "reference_scan";
inline constexpr const char* kRotationDeg = "rotation_deg";
inline constexpr const char* kScene = "scene";
inline constexpr const char* kScore = "score";
inline constexpr const char* kSecondsRegistration = "seconds_registration";
inline constexpr const char* kSecondsSampling = "seconds_sampling";
/// The alignment alone: no sampling, no reference model (table 5.9's "matching time")
inline constexpr const char* kSecondsAlign = "seconds_align";
inline constexpr const char* kSnapshotInput = "snapshot_input";
inline constexpr const char* kSnapshotReference = "snapshot_reference";
inline constexpr const char* kSuccess = "success";
inline constexpr const char* kTraceXi = "trace_xi";
inline constexpr const char* kTranslationCm = "translation_cm";

}  // namespace sextant::keys
