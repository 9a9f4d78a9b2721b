#include "sextant/posegraph/pose_graph.hpp"

#include <ceres/ceres.h>

#include <cmath>
#include <memory>

#include "sextant/posegraph/relative_pose_factor.hpp"

namespace sextant {
namespace {

std::string edge_name(std::size_t k, const PoseGraphEdge& e) {
  return "edge " + std::to_string(k) + " (" + std::to_string(e.i) + " → " + std::to_string(e.j) + ", " +
         (e.kind == EdgeKind::odometry ? "odometry" : "loop closure") + ")";
}

/// Why the graph cannot be solved as it is ("" when it can); fills the square-root informations.
std::string check_graph(const std::vector<Eigen::Isometry3d>& poses, const std::vector<PoseGraphEdge>& edges,
                        std::vector<Matrix6d>& sqrt_info) {
  for (std::size_t n = 0; n < poses.size(); ++n)
    if (!is_finite(poses[n])) return "node " + std::to_string(n) + ": initial pose not finite";
  sqrt_info.assign(edges.size(), Matrix6d::Zero());
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const PoseGraphEdge& e = edges[k];
    if (e.i >= poses.size() || e.j >= poses.size() || e.i == e.j)
      return edge_name(k, e) + ": node index out of range or a self-loop";
    if (!is_finite(e.measured)) return edge_name(k, e) + ": measurement not finite";
    if (!sqrt_information(e.information, &sqrt_info[k]))
      return edge_name(k, e) + ": information matrix singular, not positive definite or not finite";
  }
  return "";
}

}  // namespace

bool PoseGraphSettings::valid(std::string* why) const {
  const auto fail = [&](const char* text) {
    if (why) *why = text;
    return false;
  };
  if (!(loss_scale > 0.0) || !std::isfinite(loss_scale)) return fail("loss_scale must be a positive number");
  if (max_iterations < 1) return fail("max_iterations must be ≥ 1");
  if (!(function_tolerance > 0.0) || function_tolerance >= 1.0)
    return fail("function_tolerance must be in (0, 1)");
  if (threads < 1) return fail("threads must be ≥ 1");
  return true;
}

double robust_weight(RobustLoss loss, double scale, double s) {
  const double c2 = scale * scale;
  switch (loss) {
    case RobustLoss::huber: return s <= c2 ? 1.0 : scale / std::sqrt(s);
    case RobustLoss::cauchy: return 1.0 / (1.0 + s / c2);
    case RobustLoss::none: break;
  }
  return 1.0;
}

std::size_t PoseGraph::add_node(const Eigen::Isometry3d& initial) {
  poses_.push_back(initial);
  return poses_.size() - 1;
}

void PoseGraph::add_edge(std::size_t i, std::size_t j, const Eigen::Isometry3d& measured,
                         const Matrix6d& information, EdgeKind kind) {
  edges_.push_back({i, j, measured, information, kind});
}

PoseGraphReport PoseGraph::optimize(const PoseGraphSettings& settings) {
  PoseGraphReport report;
  report.nodes = poses_.size();
  for (const PoseGraphEdge& e : edges_)
    ++(e.kind == EdgeKind::odometry ? report.odometry_edges : report.loop_closure_edges);
  std::string why;
  if (!settings.valid(&why)) {
    report.message = "settings: " + why;
    return report;
  }
  std::vector<Matrix6d> sqrt_info;
  report.message = check_graph(poses_, edges_, sqrt_info);
  if (!report.message.empty()) return report;
  if (edges_.empty()) {
    report.ok = true;
    report.message = "no edges: nothing to optimise";
    return report;
  }

  // Parameters: t (3) and q (4, Eigen's x y z w) per node.
  std::vector<Eigen::Vector3d> t(poses_.size());
  std::vector<Eigen::Quaterniond> q(poses_.size());
  for (std::size_t n = 0; n < poses_.size(); ++n) {
    t[n] = poses_[n].translation();
    q[n] = Eigen::Quaterniond(poses_[n].rotation()).normalized();
  }
  ceres::Problem::Options problem_options;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  ceres::EigenQuaternionManifold quaternion_manifold;
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    const PoseGraphEdge& e = edges_[k];
    ceres::LossFunction* loss = nullptr;  // the Problem takes ownership
    const bool robust = e.kind == EdgeKind::loop_closure || settings.robust_odometry;
    if (robust && settings.loss == RobustLoss::huber) loss = new ceres::HuberLoss(settings.loss_scale);
    if (robust && settings.loss == RobustLoss::cauchy) loss = new ceres::CauchyLoss(settings.loss_scale);
    problem.AddResidualBlock(make_relative_pose_cost(e.measured, sqrt_info[k]), loss, t[e.i].data(),
                             q[e.i].coeffs().data(), t[e.j].data(), q[e.j].coeffs().data());
    problem.SetManifold(q[e.i].coeffs().data(), &quaternion_manifold);
    problem.SetManifold(q[e.j].coeffs().data(), &quaternion_manifold);
  }
  if (problem.HasParameterBlock(t[0].data())) {  // gauge: the first pose is fixed
    problem.SetParameterBlockConstant(t[0].data());
    problem.SetParameterBlockConstant(q[0].coeffs().data());
  }

  ceres::Solver::Options options;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = settings.max_iterations;
  options.function_tolerance = settings.function_tolerance;
  options.num_threads = settings.threads;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);

  report.iterations = static_cast<int>(summary.iterations.size()) - 1;  // iteration 0 is the start
  report.initial_cost = summary.initial_cost;
  report.final_cost = summary.final_cost;
  report.seconds = summary.total_time_in_seconds;
  report.message =
      ceres::TerminationTypeToString(summary.termination_type) + std::string(": ") + summary.message;
  bool finite = std::isfinite(summary.final_cost);
  for (std::size_t n = 0; n < poses_.size() && finite; ++n)
    finite = t[n].allFinite() && q[n].coeffs().allFinite() && q[n].norm() > 0.0;
  if (!summary.IsSolutionUsable() || !finite) {
    report.message = "solve failed (" + report.message + "); the initial poses are kept";
    return report;
  }
  for (std::size_t n = 1; n < poses_.size(); ++n) {         // node 0 is the gauge: kept bit for bit
    if (!problem.HasParameterBlock(t[n].data())) continue;  // not linked to anything
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = q[n].normalized().toRotationMatrix();
    T.translation() = t[n];
    poses_[n] = T;
  }
  for (const PoseGraphEdge& e : edges_) {
    if (e.kind != EdgeKind::loop_closure) continue;
    const Vector6d err = relative_pose_error(e.measured, poses_[e.i], poses_[e.j]);
    const double s = err.dot(0.5 * (e.information + e.information.transpose()) * err);
    report.closure_chi2.push_back(s);
    report.closure_weights.push_back(robust_weight(settings.loss, settings.loss_scale, s));
  }
  report.ok = true;
  return report;
}

}  // namespace sextant
