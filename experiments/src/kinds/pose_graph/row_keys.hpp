#pragma once
// Row keys (RunRow::values and ::series names) that several files of the pose_graph family use.
// A key used by one file only stays a literal there.

#include "kit/row_keys.hpp"  // the keys every family shares

namespace sextant::keys {

inline constexpr const char* kAccepted = "accepted";
inline constexpr const char* kAteErrors = "ate_errors";
inline constexpr const char* kAteM = "ate_m";
inline constexpr const char* kCandidates = "candidates";
inline constexpr const char* kClosureJ = "closure_j";
inline constexpr const char* kClosureRejection = "closure_rejection";
inline constexpr const char* kClosureSeconds = "closure_seconds";
inline constexpr const char* kClosureWeight = "closure_weight";
inline constexpr const char* kFallbackInformation = "fallback_information";
inline constexpr const char* kFalseClosures = "false_closures";
inline constexpr const char* kFalseI = "false_i";
inline constexpr const char* kFalseJ = "false_j";
inline constexpr const char* kFalseWeight = "false_weight";
inline constexpr const char* kGraphSolveIterations = "graph_solve_iterations";
inline constexpr const char* kGraphSolveSeconds = "graph_solve_seconds";
inline constexpr const char* kInformationInflation = "information_inflation";
inline constexpr const char* kRegistrationSeconds = "registration_seconds";

}  // namespace sextant::keys
