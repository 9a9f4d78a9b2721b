#pragma once
// A pose graph over scan poses (Lu–Milios' globally consistent n-scan registration, thesis §7.2):
// nodes are world ← scan poses, edges relative-pose measurements with a 6×6 information
// (relative_pose_factor.hpp). Odometry edges (consecutive registrations) enter the least-squares
// cost as they are; loop-closure edges through a robust loss ρ(s) of their squared Mahalanobis
// error s = eᵀΩe, so that one false closure cannot pull the map apart:
//
//   min  Σ_odometry eᵀΩe + Σ_closures ρ(eᵀΩe)      Huber: ρ(s) = s (s ≤ c²), 2c√s − c² beyond;
//                                                   Cauchy: ρ(s) = c²·log(1 + s/c²)
// The first node is held fixed (gauge). Solved with Ceres' Levenberg–Marquardt and sparse normal
// Cholesky; orientations live on the unit-quaternion manifold.
//
//   PoseGraph g;
//   for (pose : chained) g.add_node(pose);
//   g.add_edge(k - 1, k, step_T, step_information, EdgeKind::odometry);
//   g.add_edge(i, j, closure_T, closure_information, EdgeKind::loop_closure);
//   const PoseGraphReport r = g.optimize(settings);   // r.ok, r.message, iterations, costs
//   g.poses();                                       // the optimised poses (the initial ones when !r.ok)
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/enum_names.hpp"
#include "sextant/core/pose.hpp"

namespace sextant {

enum class EdgeKind { odometry, loop_closure };
enum class RobustLoss { none, huber, cauchy };

struct PoseGraphEdge {
  std::size_t i = 0, j = 0;
  Eigen::Isometry3d measured = Eigen::Isometry3d::Identity();  ///< T_ij* = pose of j seen from i
  Matrix6d information = Matrix6d::Identity();                 ///< Ω of [t(E); log(R(E))]
  EdgeKind kind = EdgeKind::odometry;
};

struct PoseGraphSettings {
  RobustLoss loss = RobustLoss::cauchy;  ///< on loop-closure edges (and odometry edges if robust_odometry)
  double loss_scale = 3.0;               ///< c, in units of the Mahalanobis error √(eᵀΩe)
  /// The loss on odometry edges too: one registration that converged to a wrong pose with a
  /// confident Hessian otherwise holds the whole loop against every true closure.
  bool robust_odometry = false;
  int max_iterations = 100;
  double function_tolerance = 1e-10;  ///< Ceres: relative cost change that ends the solve
  int threads = 1;

  bool valid(std::string* why) const;
};

inline constexpr EnumNames<RobustLoss, 3> kRobustLossNames{
    "robust loss",
    {{{RobustLoss::none, "none"}, {RobustLoss::huber, "huber"}, {RobustLoss::cauchy, "cauchy"}}}};
bool from_string(const std::string& text, RobustLoss* out);
std::string to_string(RobustLoss loss);

/// What the solve did. Never throws for bad data: a singular or non-finite information matrix,
/// a bad index or a failed solve is `ok = false` with the reason, and the poses stay as they were.
struct PoseGraphReport {
  bool ok = false;
  std::string message;      ///< Ceres' termination, or why nothing was solved
  int iterations = 0;       ///< Levenberg–Marquardt iterations
  double initial_cost = 0;  ///< ½ Σ ρ(eᵀΩe) before
  double final_cost = 0;    ///< … and after
  double seconds = 0;       ///< Ceres' total time
  std::size_t nodes = 0, odometry_edges = 0, loop_closure_edges = 0;
  /// Per loop-closure edge (in insertion order): eᵀΩe after the solve and the robust weight ρ'(s)
  /// it ended with (1: fully trusted; Cauchy: 1 / (1 + s/c²)).
  std::vector<double> closure_chi2, closure_weights;
};

class PoseGraph {
 public:
  /// Adds a node with its initial pose; returns its index.
  std::size_t add_node(const Eigen::Isometry3d& initial);
  void add_edge(std::size_t i, std::size_t j, const Eigen::Isometry3d& measured, const Matrix6d& information,
                EdgeKind kind);

  PoseGraphReport optimize(const PoseGraphSettings& settings);

  std::size_t size() const { return poses_.size(); }
  const std::vector<Eigen::Isometry3d>& poses() const { return poses_; }
  const std::vector<PoseGraphEdge>& edges() const { return edges_; }

 private:
  std::vector<Eigen::Isometry3d> poses_;
  std::vector<PoseGraphEdge> edges_;
};

/// The robust weight ρ'(s) of a squared error s under `loss` at scale c.
double robust_weight(RobustLoss loss, double scale, double s);

}  // namespace sextant
