#pragma once
// How well a loop-closure candidate source finds the places a trajectory truly revisits (E24):
//
//   a true revisit: scans i < j with j − i ≥ min_index_gap whose true positions are within
//     `radius` of each other;
//   precision: the fraction of the candidates (i, j) that are true revisits;
//   recall: the fraction of the revisiting scans (scans j with a true revisit i) that a true
//     candidate finds, a candidate's later scan j' finding the revisiting scans within
//     `tolerance` scans of it (sources propose one candidate every few scans, not every scan).
#include <cstddef>
#include <utility>
#include <vector>

#include "sextant/eval/trajectory_metrics.hpp"

namespace sextant {

struct RevisitSettings {
  double radius = 5.0;             ///< [m] true positions this close are the same place
  std::size_t min_index_gap = 30;  ///< scans closer in the sequence are not a revisit
  std::size_t tolerance = 4;       ///< a candidate at j' finds the revisiting scans |j − j'| < this
};

struct LoopDetectionScore {
  std::size_t candidates = 0, true_candidates = 0;
  std::size_t revisiting_scans = 0, found_scans = 0;
  double precision = 0.0;  ///< true / all candidates (NaN without candidates)
  double recall = 0.0;     ///< found / revisiting scans (NaN when nothing is revisited)
};

/// Whether scan j revisits an earlier scan, per scan of `truth` (world ← scan).
std::vector<bool> revisiting_scans(const PoseList& truth, const RevisitSettings& settings);

/// Scores `candidates` (pairs of scan indices into `truth`) against the true revisits.
LoopDetectionScore score_loop_candidates(const std::vector<std::pair<std::size_t, std::size_t>>& candidates,
                                         const PoseList& truth, const RevisitSettings& settings);

/// The accepted closures (pairs of scan indices into `truth`) whose scans are truly more than
/// `radius` apart: closures that join two different places. Pairs outside `truth` are not counted.
std::size_t count_false_closures(const std::vector<std::pair<std::size_t, std::size_t>>& accepted,
                                 const PoseList& truth, double radius);

}  // namespace sextant
