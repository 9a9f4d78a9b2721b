#pragma once
// Closing the loops of a chained trajectory (thesis §7.2; E20, E24, `sextant odometry
// --loop-closure`). The chain becomes a pose graph, one edge per registration with Ω from its
// Hessian (R = H⁻¹, eq. 3.50); loop-closure candidates come from two sources:
//
//   proximity:  the estimate comes back near an earlier pose (loop_closure.hpp). Cheap, but blind
//               once the drift exceeds the search radius;
//   descriptor: two scans look alike (Scan Context, scan_context.hpp), whatever the estimate says.
//               The guess is the descriptor's yaw alone, so these closures must also be trusted
//               (registration_quality.hpp) to be accepted.
//
// Each candidate pair is registered once (scan j onto scan i, by the caller's registration) and
// judged by judge_loop_closure. In rounds, the graph is solved with the closures accepted so far
// (trusted first without the robust loss, then with it) and the proximity search runs again along
// the better estimate, until a round finds no new pair. Before each round's solves, the stated
// information of the odometry (and, when asked, of the closures) is calibrated by variance
// component estimation (variance_components.hpp): the registrations' Hessians (eq. 3.50) are overconfident,
// and a chain whose covariance does not explain the closures' misclosures pushes true closures into the
// robust loss' flat tail.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/enum_names.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/matchers/registration_result.hpp"
#include "sextant/posegraph/loop_closure.hpp"
#include "sextant/posegraph/pose_graph.hpp"
#include "sextant/posegraph/scan_context.hpp"
#include "sextant/posegraph/variance_components.hpp"

namespace sextant {

enum class LoopCandidateSource { proximity, descriptor, both };
inline constexpr EnumNames<LoopCandidateSource, 3> kLoopCandidateSourceNames{
    "loop candidate source",
    {{{LoopCandidateSource::proximity, "proximity"},
      {LoopCandidateSource::descriptor, "descriptor"},
      {LoopCandidateSource::both, "both"}}}};
bool from_string(const std::string& text, LoopCandidateSource* out);
std::string to_string(LoopCandidateSource source);

struct LoopClosingSettings {
  LoopCandidateSource source = LoopCandidateSource::both;
  LoopClosureSettings closure;     ///< proximity candidates and the acceptance tests
  ScanContextSettings descriptor;  ///< descriptor candidates
  PoseGraphSettings graph;
  std::size_t rounds = 3;  ///< candidate searches at most (each along the last solve)
  /// Rescale the odometry and closure Ω by their estimated variance components (Helmert/Förstner)
  bool calibrate_information = true;
  /// Only the odometry's factor is estimated (σ²_c = 1): the closures are verified one by one and
  /// their stated Ω is what the robust loss' scale is measured in; from a few, often near-exact,
  /// closures σ²_c collapses towards 0 and the Cauchy loss then switches every closure off.
  VarianceComponentSettings variance = odometry_only();
  static VarianceComponentSettings odometry_only() {
    VarianceComponentSettings v;
    v.estimate_closures = false;
    return v;
  }

  bool valid(std::string* why) const;
};

/// One registration of the chain, as the graph needs it.
struct ChainStep {
  Eigen::Isometry3d relative = Eigen::Isometry3d::Identity();  ///< T_k⁻¹·T_k+1
  Matrix6d hessian = Matrix6d::Zero();
  bool converged = false;
};

struct OdometryGraph {
  PoseGraph graph;                                      ///< the chain's poses and one edge per step
  Matrix6d typical_information = Matrix6d::Identity();  ///< the median Ω of the usable steps
  std::size_t fallback_information = 0;  ///< steps that got it (not converged, or H not positive definite)
};

/// The graph over a chain (chained.size() == steps.size() + 1).
OdometryGraph odometry_graph(const std::vector<Eigen::Isometry3d>& chained,
                             const std::vector<ChainStep>& steps);

/// Element-wise median of the matrices (a "typical" information); the identity when empty or when
/// the median is not positive definite.
Matrix6d median_information(const std::vector<Matrix6d>& all);

struct ClosureAttempt {
  LoopClosureCandidate candidate;
  LoopCandidateSource source = LoopCandidateSource::proximity;
  double descriptor_distance = 1.0;  ///< Scan Context distance (descriptor candidates)
  LoopClosureDecision decision;
  Eigen::Isometry3d measured = Eigen::Isometry3d::Identity();  ///< the registration's T_i⁻¹·T_j
  double seconds = 0.0;
};

/// Registers scan j onto scan i from `guess` with the sampler seed `seed`; called concurrently.
using ClosureRegistration = std::function<RegistrationResult(
    std::size_t i, std::size_t j, const Eigen::Isometry3d& guess, std::uint64_t seed)>;

struct LoopClosingResult {
  PoseGraph graph;  ///< the odometry graph and the accepted closures (information as measured)
  std::vector<Eigen::Isometry3d> poses;  ///< the last robust solve's poses
  PoseGraphReport solve;                 ///< … and its report (closure weights in acceptance order)
  std::vector<ClosureAttempt> attempts;  ///< every candidate tried, in the order tried
  std::vector<Matrix6d> accepted_information;
  double inflation = 1.0;         ///< σ²_o: the odometry covariance factor (1 when not calibrated)
  double closure_variance = 1.0;  ///< σ²_c: the closures' covariance factor
  VarianceComponents variance;    ///< the last round's estimate
  double solve_seconds = 0.0, solve_iterations = 0.0;  ///< every round's two solves
  std::size_t accepted() const { return accepted_information.size(); }
};

/// Closes the loops of `odometry` (odometry edges only). `places` are the descriptor candidates
/// (used unless the source is proximity); `rng` draws one sampler seed per candidate, in order.
LoopClosingResult close_loops(const PoseGraph& odometry, const std::vector<PlaceMatch>& places,
                              const ClosureRegistration& register_closure,
                              const LoopClosingSettings& settings, Rng& rng);

}  // namespace sextant
