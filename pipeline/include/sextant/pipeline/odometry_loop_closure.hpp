#pragma once
// `sextant odometry --loop-closure proximity|descriptor|both`: the chained trajectory's loops
// closed in a pose graph (posegraph/loop_closing.hpp). Candidates come from the proximity search
// along the estimate, from Scan Context place recognition over the scans, or both; each is verified
// by the odometry's own matcher with the wide basin (register_pair) and must be trusted. Writes
// loop_closures.csv: one line per candidate tried.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/dataset.hpp"
#include "sextant/eval/loop_detection_metrics.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/posegraph/loop_closing.hpp"

namespace sextant {

struct OdometryLoopClosure {
  LoopClosingResult closing;
  std::size_t place_matches = 0;    ///< descriptor candidates proposed
  double descriptor_seconds = 0.0;  ///< Scan Context of every scan and the place search
  double seconds = 0.0;             ///< everything, scan loading included
};

/// Closes the loops of `chain` (scans first … first + count − 1 registered with `settings`).
OdometryLoopClosure close_odometry_loops(const Dataset& dataset, std::size_t first, std::size_t count,
                                         const OdometryResult& chain, const OdometrySettings& settings,
                                         LoopCandidateSource source);

/// How one candidate source did against the ground truth: its candidates' precision and recall
/// of the true revisits (eval/loop_detection_metrics.hpp: within the proximity radius, 10 m, at
/// least 30 scans apart; a candidate finds the revisiting scans within its stride), and how many
/// of its accepted closures join scans that are truly not the same place.
struct SourceScore {
  LoopCandidateSource source = LoopCandidateSource::proximity;
  LoopDetectionScore candidates;
  std::size_t accepted = 0, accepted_wrong = 0;
};

/// One score per source that proposed candidates (in the order proximity, descriptor).
std::vector<SourceScore> score_sources(const OdometryLoopClosure& closure,
                                       const std::vector<Eigen::Isometry3d>& truth);

/// loop_closures.csv: scans, source, descriptor distance, decision and its measures, and (with
/// ground truth) the verified registration's error against the true relative pose.
void write_loop_closures_csv(const std::filesystem::path& file, std::size_t first,
                             const OdometryLoopClosure& closure,
                             const std::optional<std::vector<Eigen::Isometry3d>>& truth);

}  // namespace sextant
