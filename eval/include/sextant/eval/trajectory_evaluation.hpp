#pragma once
// Evaluating a trajectory one already has against a reference (`sextant eval`, `sextant odometry`,
// the Python module): associate the poses (by timestamp, as evo does, or by index), align the
// estimate once (SE(3) or Sim(3) Umeyama, the first pose, or not at all), then every metric on the
// aligned estimate: ATE, RPE, KITTI drift, Wulf (eqs. 6.1–6.3) and Kümmerle (eq. 6.6). RPE, drift
// and Kümmerle are relative metrics: a rigid alignment leaves them unchanged, a Sim(3) one scales
// them with the estimate.
#include <cstddef>
#include <string>
#include <vector>

#include "sextant/core/enum_names.hpp"
#include "sextant/core/trajectory.hpp"
#include "sextant/eval/trajectory_metrics.hpp"

namespace sextant {

/// Estimate and reference poses paired one to one, in the estimate's order.
struct AssociatedPoses {
  MetricStatus status;  ///< not ok when nothing could be paired (the message says why)
  PoseList estimate, reference;
  std::vector<double> stamps;           ///< the reference's stamp of each pair [s] (index for KITTI)
  std::size_t unmatched_estimate = 0;   ///< estimate poses left without a partner
  std::size_t unmatched_reference = 0;  ///< reference poses no estimate pose took
  double largest_difference = 0.0;      ///< the largest |Δt| of a pair [s]
};

/// Pairs each estimate pose with the reference pose nearest in time, when |Δt| ≤ max_difference
/// (evo's --t_max_diff). A reference pose is taken at most once: of two estimate poses that want
/// it, the nearer keeps it and the other stays unmatched (counted, never dropped silently).
AssociatedPoses associate_by_stamp(const Trajectory& estimate, const Trajectory& reference,
                                   double max_difference);

/// Pairs pose i with pose i (files without time, KITTI): the lengths must agree.
AssociatedPoses associate_by_index(const Trajectory& estimate, const Trajectory& reference);

struct TrajectoryEvaluationSettings {
  Alignment alignment = Alignment::se3;
  RpeSettings rpe;  ///< default: consecutive poses
  KittiDriftSettings drift;
};

struct TrajectoryEvaluation {
  MetricStatus status;  ///< the first metric that failed, if any
  AteResult ate;        ///< its `alignment` is the one applied to the estimate
  PoseList aligned_estimate;
  RpeResult rpe;
  KittiDriftResult drift;  ///< segments = 0 when the path is shorter than the shortest length
  WulfResult wulf;
  KummerleResult kummerle;  ///< over consecutive poses
};

TrajectoryEvaluation evaluate_trajectory(const PoseList& estimate, const PoseList& reference,
                                         const TrajectoryEvaluationSettings& settings = {});

inline constexpr EnumNames<Alignment, 4> kAlignmentNames{"alignment",
                                                         {{{Alignment::se3, "se3"},
                                                           {Alignment::sim3, "sim3"},
                                                           {Alignment::origin, "origin"},
                                                           {Alignment::none, "none"}}}};
bool from_string(const std::string& text, Alignment* out);
std::string to_string(Alignment alignment);

}  // namespace sextant
