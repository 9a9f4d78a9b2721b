// The ICP loop shared by icp_p2p and icp_p2l: correspondences by nearest neighbour within a
// distance, one closed-form or linearised increment per iteration, stop on ‖Δξ‖ < ε.
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "icp/icp_steps.hpp"
#include "icp/kd_tree.hpp"
#include "sextant/core/checked_settings.hpp"
#include "sextant/matchers/icp.hpp"

namespace sextant {

namespace {

/// Unit normal of each reference point by PCA of its k nearest neighbours (the eigenvector of
/// the smallest covariance eigenvalue); NaN where the neighbourhood is too small or collinear.
std::vector<Eigen::Vector3f> pca_normals(const std::vector<Eigen::Vector3f>& points, const KdTree& tree,
                                         int k) {
  std::vector<Eigen::Vector3f> normals(points.size(), Eigen::Vector3f::Constant(NAN));
  std::vector<KdTree::Neighbour> neighbours;
  for (std::size_t i = 0; i < points.size(); ++i) {
    tree.k_nearest(points[i], static_cast<std::size_t>(k), neighbours);
    if (neighbours.size() < 3) continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& n : neighbours) mean += points[n.index].cast<double>();
    mean /= static_cast<double>(neighbours.size());
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    for (const auto& n : neighbours) {
      const Eigen::Vector3d d = points[n.index].cast<double>() - mean;
      C.noalias() += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C);
    const Eigen::Vector3d lambda = eig.eigenvalues();                   // ascending
    if (!(lambda[2] > 0.0) || lambda[1] <= 1e-6 * lambda[2]) continue;  // a line, not a surface
    normals[i] = eig.eigenvectors().col(0).cast<float>();
  }
  return normals;
}

class IcpMatcher final : public Matcher {
 public:
  IcpMatcher(IcpObjective objective, const IcpSettings& settings)
      : objective_(objective), settings_(settings) {}

  std::string name() const override {
    return objective_ == IcpObjective::kPointToPoint ? "icp_p2p" : "icp_p2l";
  }

  void set_reference(const PointCloud& reference) override {
    reference_.assign(reference.points().begin(), reference.points().end());
    tree_.build(reference_);
    normals_.clear();
    if (objective_ == IcpObjective::kPointToPlane)
      normals_ = pca_normals(reference_, tree_, settings_.normal_neighbours);
  }

  RegistrationResult align(const PointCloud& input, const Eigen::Isometry3d& initial) override {
    const auto start = std::chrono::steady_clock::now();
    RegistrationResult result = run(input, initial);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }

 private:
  RegistrationResult run(const PointCloud& input, const Eigen::Isometry3d& initial) const {
    if (!is_finite(initial)) return not_started(Termination::kNonFiniteInput, input.size(), initial);
    RegistrationResult result;
    result.input_points = input.size();
    result.T = initial;
    result.free = settings_.dof;
    if (tree_.empty() || input.empty()) {
      result.why = Termination::kEmptyInput;
      return result;
    }
    Eigen::Isometry3d T = initial;
    Correspondences pairs;
    for (int iteration = 1; iteration <= settings_.max_iterations; ++iteration) {
      find_correspondences(input, T, pairs);
      result.matched_points = pairs.size();
      if (pairs.size() < static_cast<std::size_t>(settings_.min_correspondences)) {
        result.why = Termination::kTooFewCorrespondences;
        return result;
      }
      const IcpStep step = objective_ == IcpObjective::kPointToPoint
                               ? point_to_point_step(pairs, settings_.dof)
                               : point_to_plane_step(pairs, settings_.dof);
      if (!step.ok) {
        result.why = Termination::kSolverFailure;
        return result;
      }
      T = step.delta * T;
      if (!is_finite(T)) {
        result.why = Termination::kDiverged;
        return result;
      }
      result.T = T;
      result.iterations = iteration;
      result.H = step.H;
      result.score = step.score_after;
      const double step_norm = step.xi.norm();
      result.trace.push_back(
          IterationTrace{iteration, 0, step.score_after, step_norm, to_pose6(T).vector(), pairs.size()});
      if (step_norm < settings_.epsilon) {
        result.converged = true;
        result.why = Termination::kConverged;
        return result;
      }
    }
    result.why = Termination::kMaxIterations;
    return result;
  }

  /// Nearest reference point (with a valid normal for p2l) of each mapped input point.
  void find_correspondences(const PointCloud& input, const Eigen::Isometry3d& T,
                            Correspondences& pairs) const {
    pairs.clear();
    const float max_d2 =
        static_cast<float>(settings_.max_correspondence_distance * settings_.max_correspondence_distance);
    const bool plane = objective_ == IcpObjective::kPointToPlane;
    KdTree::Neighbour n;
    for (const Eigen::Vector3f& point : input.points()) {
      const Eigen::Vector3d p = T * point.cast<double>();
      if (!tree_.nearest(p.cast<float>(), max_d2, &n)) continue;  // also skips non-finite points
      if (plane && !normals_[n.index].allFinite()) continue;
      pairs.input.push_back(p);
      pairs.reference.push_back(reference_[n.index].cast<double>());
      if (plane) pairs.normals.push_back(normals_[n.index].cast<double>());
    }
  }

  IcpObjective objective_;
  IcpSettings settings_;
  std::vector<Eigen::Vector3f> reference_;
  std::vector<Eigen::Vector3f> normals_;
  KdTree tree_;
};

}  // namespace

std::unique_ptr<Matcher> make_icp(IcpObjective objective, const IcpSettings& settings) {
  return std::make_unique<IcpMatcher>(
      objective, checked(settings, objective == IcpObjective::kPointToPlane ? "icp_p2l" : "icp_p2p"));
}

}  // namespace sextant
