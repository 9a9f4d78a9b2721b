#pragma once
// `place_recognition` (E24; thesis §7.2: "an independent loop detection mechanism"): ML-NDT
// odometry over the campus, chained once per experiment; one run closes its loops
// (posegraph/loop_closing.hpp) with one candidate source — the proximity search along the estimate,
// Scan Context place recognition, or both — after the chain's drift has been inflated by
// `drift_yaw_deg_per_scan` (sweep axis: every step turned that much more than it was, so the
// estimate drifts past the proximity radius). Every candidate must be verified by a trusted ML-NDT
// registration with the wide basin. Recorded per run: the candidates' precision and recall against
// the true revisits, the accepted closures that are wrong, ATE before and after, and the cost of
// the descriptors and their search.
#include <string>
#include <vector>

#include "sextant/experiments/experiment_config.hpp"
#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_plan.hpp"
#include "sextant/experiments/run_row.hpp"

namespace sextant {

inline constexpr char kDriftAxis[] = "drift_yaw_deg_per_scan";

/// The row keys both files of the family use.
namespace place_keys {
inline constexpr const char* kChainedAte = "chained_ate_m";
inline constexpr const char* kClosedAte = "closed_ate_m";
inline constexpr const char* kChainedErrors = "chained_errors";
inline constexpr const char* kClosedErrors = "closed_errors";
inline constexpr const char* kChained = "chained_trajectory";
inline constexpr const char* kClosed = "closed_trajectory";
inline constexpr const char* kTruth = "truth";
inline constexpr const char* kCandidates = "candidates";
inline constexpr const char* kPrecision = "precision";
inline constexpr const char* kRecall = "recall";
inline constexpr const char* kAccepted = "accepted";
inline constexpr const char* kAcceptedWrong = "accepted_wrong";
inline constexpr const char* kPlaceMatches = "place_matches";
inline constexpr const char* kDescriptorMs = "descriptor_ms_per_scan";
inline constexpr const char* kSearchMs = "place_search_ms_per_scan";
inline constexpr const char* kClosingSeconds = "closing_seconds";
}  // namespace place_keys

/// The report (place_recognition/report.cpp): per source and drift, the candidates' precision and
/// recall, the closures and the ATE; the trajectories at the largest drift; the claims.
ReportSection place_recognition_report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                                       const std::vector<const RunRow*>& rows);

}  // namespace sextant
