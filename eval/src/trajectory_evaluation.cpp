#include "sextant/eval/trajectory_evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sextant {
namespace {

MetricStatus failed(const std::string& message) {
  return {false, message};
}

/// The similarity applied to a whole pose: R' = R_a·R, t' = s·R_a·t + t_a.
Eigen::Isometry3d apply(const Similarity3& a, const Eigen::Isometry3d& T) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = a.rotation * T.linear();
  out.translation() = a.apply(T.translation());
  return out;
}

}  // namespace

AssociatedPoses associate_by_stamp(const Trajectory& estimate, const Trajectory& reference,
                                   double max_difference) {
  AssociatedPoses out;
  if (!(max_difference >= 0.0)) {
    out.status = failed("the largest time difference must be ≥ 0");
    return out;
  }
  // Sorted reference stamps; for each estimate pose the nearest one.
  std::vector<std::size_t> order(reference.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return reference[a].stamp < reference[b].stamp; });
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> partner(estimate.size(), kNone);  // reference index per estimate pose
  std::vector<std::size_t> taken_by(reference.size(), kNone);
  for (std::size_t e = 0; e < estimate.size(); ++e) {
    const double t = estimate[e].stamp;
    const auto it = std::lower_bound(order.begin(), order.end(), t,
                                     [&](std::size_t r, double v) { return reference[r].stamp < v; });
    std::size_t best = kNone;
    double best_gap = max_difference;
    for (auto c = it == order.begin() ? it : it - 1; c != order.end() && c <= it; ++c) {
      const double gap = std::abs(reference[*c].stamp - t);
      if (gap <= best_gap) best = *c, best_gap = gap;
    }
    if (best == kNone) continue;
    const std::size_t rival = taken_by[best];
    if (rival != kNone) {
      if (std::abs(estimate[rival].stamp - reference[best].stamp) <= best_gap) continue;
      partner[rival] = kNone;
    }
    partner[e] = best;
    taken_by[best] = e;
  }
  for (std::size_t e = 0; e < estimate.size(); ++e) {
    if (partner[e] == kNone) {
      ++out.unmatched_estimate;
      continue;
    }
    const StampedPose& r = reference[partner[e]];
    out.estimate.push_back(estimate[e].pose);
    out.reference.push_back(r.pose);
    out.stamps.push_back(r.stamp);
    out.largest_difference = std::max(out.largest_difference, std::abs(r.stamp - estimate[e].stamp));
  }
  out.unmatched_reference = reference.size() - out.reference.size();
  if (out.estimate.empty())
    out.status = failed("no estimate pose has a reference pose within " + std::to_string(max_difference) +
                        " s (are both files stamped on the same clock?)");
  return out;
}

AssociatedPoses associate_by_index(const Trajectory& estimate, const Trajectory& reference) {
  AssociatedPoses out;
  if (estimate.size() != reference.size()) {
    out.status = failed("the estimate has " + std::to_string(estimate.size()) + " poses and the reference " +
                        std::to_string(reference.size()) + ": without timestamps, poses pair by index");
    return out;
  }
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    out.estimate.push_back(estimate[i].pose);
    out.reference.push_back(reference[i].pose);
    out.stamps.push_back(reference[i].stamp);
  }
  return out;
}

TrajectoryEvaluation evaluate_trajectory(const PoseList& estimate, const PoseList& reference,
                                         const TrajectoryEvaluationSettings& settings) {
  TrajectoryEvaluation r;
  r.ate = absolute_trajectory_error(estimate, reference, settings.alignment);
  if (!r.ate.status.ok) {
    r.status = r.ate.status;
    return r;
  }
  for (const Eigen::Isometry3d& T : estimate) r.aligned_estimate.push_back(apply(r.ate.alignment, T));
  r.rpe = relative_pose_error(r.aligned_estimate, reference, settings.rpe);
  r.drift = kitti_drift(r.aligned_estimate, reference, settings.drift);
  r.wulf = wulf_metric(r.aligned_estimate, reference);
  r.kummerle = kummerle_metric(r.aligned_estimate, reference);
  // A path shorter than the shortest drift segment has no drift (segments = 0), which is no failure:
  // the drift's input checks are the RPE's.
  const MetricStatus drift = r.drift.segments == 0 ? MetricStatus{} : r.drift.status;
  const MetricStatus* statuses[] = {&r.rpe.status, &drift, &r.wulf.status, &r.kummerle.status};
  for (const MetricStatus* s : statuses) {
    if (!s->ok) {
      r.status = *s;
      break;
    }
  }
  return r;
}

bool from_string(const std::string& text, Alignment* out) {
  return from_name(kAlignmentNames, text, out);
}

std::string to_string(Alignment alignment) {
  return name_of(kAlignmentNames, alignment);
}

}  // namespace sextant
