#include "sextant/eval/loop_detection_metrics.hpp"

#include <algorithm>
#include <limits>

namespace sextant {
namespace {

bool same_place(const PoseList& truth, std::size_t i, std::size_t j, double radius) {
  return (truth[i].translation() - truth[j].translation()).norm() <= radius;
}

}  // namespace

std::vector<bool> revisiting_scans(const PoseList& truth, const RevisitSettings& settings) {
  std::vector<bool> out(truth.size(), false);
  for (std::size_t j = settings.min_index_gap; j < truth.size(); ++j)
    for (std::size_t i = 0; i + settings.min_index_gap <= j && !out[j]; ++i)
      out[j] = same_place(truth, i, j, settings.radius);
  return out;
}

LoopDetectionScore score_loop_candidates(const std::vector<std::pair<std::size_t, std::size_t>>& candidates,
                                         const PoseList& truth, const RevisitSettings& settings) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  LoopDetectionScore s;
  const std::vector<bool> revisiting = revisiting_scans(truth, settings);
  std::vector<bool> found(truth.size(), false);
  for (const auto& [i, j] : candidates) {
    if (i >= truth.size() || j >= truth.size()) continue;
    ++s.candidates;
    if (j < i + settings.min_index_gap || !same_place(truth, i, j, settings.radius)) continue;
    ++s.true_candidates;
    const std::size_t from = j + 1 > settings.tolerance ? j + 1 - settings.tolerance : 0;
    for (std::size_t k = from; k < std::min(truth.size(), j + settings.tolerance); ++k) found[k] = true;
  }
  for (std::size_t j = 0; j < truth.size(); ++j) {
    s.revisiting_scans += revisiting[j] ? 1 : 0;
    s.found_scans += revisiting[j] && found[j] ? 1 : 0;
  }
  s.precision = s.candidates ? double(s.true_candidates) / double(s.candidates) : kNaN;
  s.recall = s.revisiting_scans ? double(s.found_scans) / double(s.revisiting_scans) : kNaN;
  return s;
}

std::size_t count_false_closures(const std::vector<std::pair<std::size_t, std::size_t>>& accepted,
                                 const PoseList& truth, double radius) {
  std::size_t wrong = 0;
  for (const auto& [i, j] : accepted)
    if (i < truth.size() && j < truth.size() && !same_place(truth, i, j, radius)) ++wrong;
  return wrong;
}

}  // namespace sextant
