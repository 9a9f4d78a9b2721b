#pragma once
// Loop closures for the pose graph: candidates where the estimated trajectory comes back near an
// earlier pose, and the test that accepts or rejects the registration that verifies one.
//
//   candidates: pose j against the earlier poses i with j − i ≥ min_index_gap and a path of
//     ≥ min_path_gap metres between them; the nearest such i with ‖p_i − p_j‖ ≤ radius is a
//     candidate; candidates are at least `stride` scans apart (in j), so a long revisit yields
//     a closure every few scans instead of one per scan;
//   verification: scan j registered onto scan i (ML-NDT in the experiments) from the graph's
//     relative guess T_i⁻¹·T_j; accepted when it converged, its mean score per matched point and
//     its matched fraction pass their thresholds, its correction of the guess stays within
//     max_correction (the guess comes from drifting odometry, a jump further than the drift can
//     explain is a wrong basin), its Hessian is positive definite and (with require_trust) the
//     registration is trusted (registration_quality.hpp); then the edge's information
//     is Ω from H (R = H⁻¹, eq. 3.50, relative_pose_factor.hpp), times information_scale.
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/pose.hpp"
#include "sextant/matchers/registration_result.hpp"

namespace sextant {

struct LoopClosureSettings {
  double radius = 10.0;               ///< [m] candidate when the estimated poses are this close
  std::size_t min_index_gap = 30;     ///< scans between i and j at least
  double min_path_gap = 60.0;         ///< [m] estimated path length between i and j at least
  std::size_t stride = 4;             ///< scans between consecutive candidates' j at least
  double max_mean_score = 6.0;        ///< accepted when score / matched points ≤ this
  double min_matched_fraction = 0.5;  ///< … and matched / input points ≥ this
  double max_correction_m = 8.0;      ///< … and the correction of the guess ≤ this [m]
  double max_correction_deg = 20.0;   ///< … and ≤ this [deg]
  double information_scale = 1.0;     ///< Ω of an accepted closure = scale · J⁻ᵀ·H·J⁻¹
  /// … and the registration must be trusted (registration_quality.hpp; false for E20, whose
  /// acceptance tests predate the trust checks).
  bool require_trust = false;

  bool valid(std::string* why) const;
};

struct LoopClosureCandidate {
  std::size_t i = 0, j = 0;                                 ///< i < j
  double distance = 0.0;                                    ///< ‖p_i − p_j‖ of the estimate [m]
  Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();  ///< T_i⁻¹·T_j of the estimate
};

/// The candidates along `poses` (world ← scan), in increasing j.
std::vector<LoopClosureCandidate> find_loop_closure_candidates(const std::vector<Eigen::Isometry3d>& poses,
                                                               const LoopClosureSettings& settings);

/// Which test rejected a closure (none: accepted), in the order they are applied.
enum class ClosureRejection { none, not_converged, score, matched_fraction, correction, hessian, untrusted };

struct LoopClosureDecision {
  bool accepted = false;
  ClosureRejection rejection = ClosureRejection::none;
  std::string reason;  ///< why rejected ("" when accepted)
  double mean_score = 0.0, matched_fraction = 0.0;
  double correction_m = 0.0, correction_deg = 0.0;
  Matrix6d information = Matrix6d::Zero();  ///< when accepted
};

/// Accepts or rejects the registration `r` (scan j onto scan i, started from `candidate.guess`).
LoopClosureDecision judge_loop_closure(const RegistrationResult& r, const LoopClosureCandidate& candidate,
                                       const LoopClosureSettings& settings);

}  // namespace sextant
