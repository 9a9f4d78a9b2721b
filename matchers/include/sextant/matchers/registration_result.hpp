#pragma once
// What every matcher returns (docs/design.md, "Module contracts"). A diverged registration is a
// result with converged = false and a reason, never an exception.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/pose.hpp"
#include "sextant/matchers/dof_mask.hpp"

namespace sextant {

enum class Termination {
  kConverged,              ///< ‖Δξ‖ < ε in the last layer
  kMaxIterations,          ///< iteration cap reached
  kTooFewCorrespondences,  ///< fewer matched points than the problem needs
  kNonFiniteInput,         ///< NaN/Inf in the initial guess or the data
  kEmptyInput,             ///< empty reference or input cloud
  kSolverFailure,          ///< linear solve or line search failed
  kDiverged,               ///< the estimate left the plausible region
  kGridTooLarge,           ///< the reference's grid would exceed the cell cap (cells too small for it)
  kNoGaussians,            ///< no cell of the reference holds enough spread points for a Gaussian
};

std::string to_string(Termination why);

/// One optimiser iteration, for convergence plots (E1).
struct IterationTrace {
  int iteration = 0;
  int layer = 0;                   ///< ML-NDT layer (0 when the matcher has none)
  double score = 0.0;              ///< objective after the step
  double step_norm = 0.0;          ///< ‖Δξ‖
  Vector6d xi = Vector6d::Zero();  ///< [tx ty tz α β γ] after the step, eq. (3.12)
  std::size_t matched_points = 0;
};

/// Whether to believe a registration (registration_quality.hpp says how each is decided).
enum class Trust { kOk, kNotConverged, kDegenerate, kLowOverlap, kSuspect };

/// "ok", "not_converged", "degenerate", "low_overlap", "suspect".
std::string to_string(Trust trust);

/// The assessment of a registration's solution (assess_registration, registration_quality.hpp).
struct RegistrationQuality {
  bool assessed = false;          ///< false: nobody assessed this result (the fields mean nothing)
  double overlap = 0.0;           ///< matched / input points [fraction]
  double constraint_ratio = 0.0;  ///< weakest / strongest eigenvalue of the metre-scaled H (NaN: no H)
  double fit_ratio = 0.0;         ///< mean matched score / its prediction (0: no prediction)
  Trust trust = Trust::kNotConverged;
  std::string reason;  ///< empty when ok, else one line that says why not
  /// Suspect only because another solution passes the same checks far away (the result alone
  /// passes them)
  bool ambiguous = false;
  bool trusted() const { return assessed && trust == Trust::kOk; }
};

struct RegistrationResult {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();  ///< maps input points into the reference frame
  bool converged = false;
  Termination why = Termination::kMaxIterations;
  int iterations = 0;
  Matrix6d H = Matrix6d::Zero();  ///< Hessian of the score at the solution; R = H⁻¹, eq. (3.50)
  /// The Hessian whose conditioning the degeneracy check reads (registration_quality.hpp); zero: H.
  /// ML-NDT's precision stage sets it to the last layer's at the final pose, where its other trust
  /// checks are measured too: the stage's thin Gaussians stiffen the surfaces' normals a hundredfold,
  /// not the directions the surfaces leave free, and the check's bar was set on the layers' Gaussians.
  Matrix6d constraint_hessian = Matrix6d::Zero();
  /// The parameters the registration was free to move (its settings' DOF mask): the degeneracy check
  /// weighs H over these, and a free parameter nothing constrains (a zero row) is unconstrained
  DofMask free;
  double score = 0.0;
  /// Mean score of a matched point at the solution (the penalties of unmatched and rejected points
  /// left out), and what the score's model predicts for it at the right pose (3 for the Mahalanobis
  /// score: a χ² with 3 DOF); 0 and 0 when the matcher has no such model.
  double mean_matched_score = 0.0;
  double predicted_matched_score = 0.0;
  RegistrationQuality quality;  ///< filled by assess_registration (match_pair does)
  std::vector<IterationTrace> trace;
  std::size_t matched_points = 0;
  std::size_t input_points = 0;  ///< points offered to the matcher after sampling
  double seconds = 0.0;
  /// Empty, or what the matcher fell back to and why (e.g. FbML-NDT on a degenerate feature sample:
  /// "feature sample degenerate (normals span fewer than three directions (0.0004)): added 5120 GBS points").
  std::string fallback;
  /// Other solutions the matcher reached and did not choose: the wide basin's other refined starts,
  /// refine_first's other run (each without trace or alternatives of its own). assess_registration
  /// calls the result ambiguous (suspect) when one of them passes the same checks far from it.
  std::vector<RegistrationResult> alternatives;
  /// Where the pyramid ended before ML-NDT's precision stage moved the pose to T (none: no such stage
  /// ran). The alternatives end where the pyramid ends, so assess_registration tells them apart from
  /// this pose: two poses compared at one stage's precision, not the precision stage's step (tenths of
  /// a metre on a sparse solid-state scan) taken for a second answer.
  std::optional<Eigen::Isometry3d> before_precision;

  /// One line: "converged after 12 iterations (converged), score …, 1234 matched, 0.012 s[; fallback: …]".
  std::string summary() const;
};

/// A registration that could not start (e.g. no reference model): not converged for `why`, T the
/// initial guess when it is finite (identity otherwise).
RegistrationResult not_started(Termination why, std::size_t input_points, const Eigen::Isometry3d& initial);

}  // namespace sextant
