// PCL's NDT, ICP and GICP behind our Matcher interface (the only file of the module that
// includes PCL's registration headers). Reference-side work — PCL's voxel grid, the target
// k-d tree, GICP's target covariances — is done in set_reference(), so align() times only the
// registration, as for our own matchers.

// GCC 12 reports a false -Warray-bounds inside Eigen's SSE loads when PCL's ICP instantiates
// Eigen::umeyama on float 3×N maps; it must be silenced before any Eigen header is read.
#pragma GCC diagnostic ignored "-Warray-bounds"
#include <chrono>
#include <cmath>
#include <exception>
#include <stdexcept>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/registration/gicp.h>
#include <pcl/registration/icp.h>
#include <pcl/registration/ndt.h>
#include <pcl/search/kdtree.h>

#include "sextant/core/checked_settings.hpp"
#include "sextant/matchers/pcl_peers.hpp"

namespace sextant {

namespace {

using PclPoint = pcl::PointXYZ;
using PclCloud = pcl::PointCloud<PclPoint>;
using PclTree = pcl::search::KdTree<PclPoint>;
constexpr double kMaxPclGuess = 1e6;  ///< [m]

/// Our cloud as a PCL cloud, without non-finite points (PCL's registration assumes dense clouds).
PclCloud::Ptr to_pcl(const PointCloud& cloud) {
  auto out = std::make_shared<PclCloud>();
  out->reserve(cloud.size());
  for (const Eigen::Vector3f& p : cloud.points()) {
    if (p.allFinite()) out->push_back(PclPoint(p.x(), p.y(), p.z()));
  }
  out->width = static_cast<std::uint32_t>(out->size());
  out->height = 1;
  out->is_dense = true;
  return out;
}

/// PCL registrations with their iteration count (a protected member) made readable.
template <class Base>
class Exposed : public Base {
 public:
  int iterations() const { return this->nr_iterations_; }
};

class PclNdt final : public Exposed<pcl::NormalDistributionsTransform<PclPoint, PclPoint>> {
 public:
  /// Negated Hessian of PCL's NDT score (a likelihood PCL maximises) at `T`, from PCL's own
  /// analytic derivatives [Magnusson 2009, eqs. 6.12–6.13]; parameters [t, Rx·Ry·Rz angles].
  Matrix6d hessian_at(const PclCloud& aligned, const Eigen::Matrix4d& T) {
    Eigen::Matrix<double, 6, 1> x, gradient;
    const Eigen::Matrix3d R = T.topLeftCorner<3, 3>();
    x << T.topRightCorner<3, 1>(), R.eulerAngles(0, 1, 2);
    Eigen::Matrix<double, 6, 6> hessian;
    computeDerivatives(gradient, hessian, aligned, x, true);
    return -hessian;
  }
};

class PclIcp final : public Exposed<pcl::IterativeClosestPoint<PclPoint, PclPoint>> {};

class PclGicp final : public Exposed<pcl::GeneralizedIterativeClosestPoint<PclPoint, PclPoint>> {
 public:
  /// Computes the target's local covariances now rather than in the first align().
  void prepare_target() {
    auto covariances = std::make_shared<MatricesVector>();
    computeCovariances<PclPoint>(target_, tree_, *covariances);
    if (covariances->size() == target_->size()) target_covariances_ = covariances;
  }
};

/// The shared wrapper: guards against input PCL does not handle, runs PCL, fills the result.
template <class Registration>
class PclPeer : public Matcher {
 public:
  void set_reference(const PointCloud& reference) override {
    target_ = to_pcl(reference);
    tree_ = std::make_shared<PclTree>();
    if (target_->empty()) return;
    registration_.setInputTarget(target_);
    tree_->setInputCloud(target_);
    registration_.setSearchMethodTarget(tree_, true);  // built once here, not in align()
    prepare_target();
  }

  RegistrationResult align(const PointCloud& input, const Eigen::Isometry3d& initial) override {
    const auto start = std::chrono::steady_clock::now();
    if (!is_finite(initial)) return not_started(Termination::kNonFiniteInput, input.size(), initial);
    // PCL asserts (the process aborts) on guesses like 1e39 m: no PCL call with one.
    if (initial.translation().norm() > kMaxPclGuess)
      return not_started(Termination::kDiverged, input.size(), initial);
    RegistrationResult result;
    result.input_points = input.size();
    result.T = initial;
    const PclCloud::Ptr source = to_pcl(input);
    if (!target_ || target_->empty() || source->empty()) {
      result.why = Termination::kEmptyInput;
      return result;
    }
    if (source->size() < min_points() || target_->size() < min_points()) {
      result.why = Termination::kTooFewCorrespondences;
      return result;
    }
    PclCloud aligned;
    try {
      registration_.setInputSource(source);
      registration_.align(aligned, initial.matrix().cast<float>());
    } catch (const std::exception&) {  // e.g. pcl::SolverDidntConvergeException
      result.why = Termination::kSolverFailure;
      result.seconds = seconds_since(start);
      return result;
    }
    result.seconds = seconds_since(start);
    result.iterations = registration_.iterations();
    const Eigen::Matrix4d T = registration_.getFinalTransformation().template cast<double>();
    if (!T.allFinite()) {
      result.why = Termination::kDiverged;
      return result;
    }
    result.T.matrix() = T;
    classify(result);
    if (aligned.size() == source->size()) {
      result.score = registration_.getFitnessScore();
      result.matched_points = points_within(aligned, overlap_distance());
      result.H = hessian(aligned, T);
    }
    return result;
  }

 protected:
  virtual std::size_t min_points() const { return 3; }
  virtual void prepare_target() {}
  /// Aligned points with a reference point within `distance`: the overlap the trust check needs
  /// (PCL's fitness score averages over the matched points only, so it cannot tell).
  std::size_t points_within(const PclCloud& aligned, double distance) const {
    std::size_t n = 0;
    pcl::Indices index(1);
    std::vector<float> squared(1);
    const float limit = static_cast<float>(distance * distance);
    for (const PclPoint& p : aligned.points)
      if (tree_->nearestKSearch(p, 1, index, squared) == 1 && squared[0] <= limit) ++n;
    return n;
  }

  /// How close an aligned point must come to the reference to count as matched [m].
  virtual double overlap_distance() { return registration_.getMaxCorrespondenceDistance(); }

  virtual Matrix6d hessian(const PclCloud&, const Eigen::Matrix4d&) {
    return Matrix6d::Zero();
  }  // not exposed
  virtual int max_iterations() const = 0;

  /// PCL reports "converged" also when it stopped at the iteration cap; we keep them apart.
  void classify(RegistrationResult& result) const {
    if (!registration_.hasConverged()) {
      result.why = result.iterations == 0 ? Termination::kTooFewCorrespondences : Termination::kSolverFailure;
    } else if (result.iterations >= max_iterations()) {
      result.why = Termination::kMaxIterations;
    } else {
      result.converged = true;
      result.why = Termination::kConverged;
    }
  }

  static double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  Registration registration_;
  PclCloud::Ptr target_;
  PclTree::Ptr tree_;
};

class PclNdtMatcher final : public PclPeer<PclNdt> {
 public:
  explicit PclNdtMatcher(const PclNdtSettings& s) : settings_(s) {
    registration_.setResolution(static_cast<float>(s.resolution));
    registration_.setStepSize(s.step_size);
    registration_.setTransformationEpsilon(s.epsilon);
    registration_.setMaximumIterations(s.max_iterations);
    registration_.setOulierRatio(s.outlier_ratio);
  }
  std::string name() const override { return "pcl_ndt"; }

 private:
  int max_iterations() const override { return settings_.max_iterations; }
  /// NDT has no correspondence distance: a point within one cell of the reference is in its model.
  double overlap_distance() override { return settings_.resolution; }
  Matrix6d hessian(const PclCloud& aligned, const Eigen::Matrix4d& T) override {
    return registration_.hessian_at(aligned, T);
  }
  PclNdtSettings settings_;
};

class PclIcpMatcher final : public PclPeer<PclIcp> {
 public:
  explicit PclIcpMatcher(const PclIcpSettings& s) : settings_(s) {
    registration_.setMaxCorrespondenceDistance(s.max_correspondence_distance);
    registration_.setMaximumIterations(s.max_iterations);
    registration_.setTransformationEpsilon(s.epsilon);
    registration_.setEuclideanFitnessEpsilon(s.fitness_epsilon);
  }
  std::string name() const override { return "pcl_icp"; }

 private:
  int max_iterations() const override { return settings_.max_iterations; }
  PclIcpSettings settings_;
};

class PclGicpMatcher final : public PclPeer<PclGicp> {
 public:
  explicit PclGicpMatcher(const PclGicpSettings& s) : settings_(s) {
    registration_.setMaxCorrespondenceDistance(s.max_correspondence_distance);
    registration_.setMaximumIterations(s.max_iterations);
    registration_.setTransformationEpsilon(s.epsilon);
    registration_.setCorrespondenceRandomness(s.correspondence_randomness);
    registration_.setMaximumOptimizerIterations(s.max_optimizer_iterations);
  }
  std::string name() const override { return "pcl_gicp"; }

 private:
  // GICP needs k neighbours per point for its covariances, in both clouds.
  std::size_t min_points() const override {
    return static_cast<std::size_t>(settings_.correspondence_randomness);
  }
  void prepare_target() override {
    if (target_->size() >= min_points()) registration_.prepare_target();
  }
  int max_iterations() const override { return settings_.max_iterations; }
  PclGicpSettings settings_;
};

}  // namespace

std::unique_ptr<Matcher> make_pcl_ndt(const PclNdtSettings& settings) {
  return std::make_unique<PclNdtMatcher>(checked(settings, "pcl_ndt"));
}

std::unique_ptr<Matcher> make_pcl_icp(const PclIcpSettings& settings) {
  return std::make_unique<PclIcpMatcher>(checked(settings, "pcl_icp"));
}

std::unique_ptr<Matcher> make_pcl_gicp(const PclGicpSettings& settings) {
  return std::make_unique<PclGicpMatcher>(checked(settings, "pcl_gicp"));
}

}  // namespace sextant
