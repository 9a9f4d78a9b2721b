#pragma once
// E20's report layout (the `pose_graph` kind): what its files share.
//   pose_graph/report.cpp  — notes, the metrics tables (whole route, and each shorter filter's
//                            prefix), the loop-closure table
//   pose_graph/figures.cpp — top-down trajectories with the loop closures, error vs scan
//   pose_graph/claims.cpp  — the claims, decided on bootstrap intervals of batch means
#include <string>
#include <vector>

#include "kit/row_groups.hpp"
#include "pose_graph/params.hpp"
#include "sextant/eval/trajectory_metrics.hpp"
#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_plan.hpp"
#include "sextant/experiments/run_row.hpp"

namespace sextant {

/// The trajectories of the odometry method the report draws: prefix "chained_", "graph_",
/// "false_robust_", "false_plain_"; label as shown in tables and legends.
struct TrajectoryKind {
  std::string prefix, label, color;
};
std::vector<TrajectoryKind> graph_trajectories(const std::string& matcher_name);

ReportSection pose_graph_report(const ExperimentConfig& config, const PoseGraphParams& params,
                                const std::vector<PoseGraphMethod>& methods, const std::vector<RunSpec>& runs,
                                const std::vector<const RunRow*>& rows);

/// Figures of the first repetition.
std::vector<ReportFigure> pose_graph_figures(const MethodRows& odometry,
                                             const std::vector<MethodRows>& filters);
/// The claims (pose_graph/claims.cpp).
std::vector<Claim> pose_graph_claims(const ExperimentConfig& config, const PoseGraphParams& params,
                                     const MethodRows& odometry);

/// Median of the finite values (NaN when none).
double median_finite(std::vector<double> values);

}  // namespace sextant
