#pragma once
// The one optimiser loop shared by NDT and ML-NDT (docs/design.md, "Module contracts"). An
// objective has one or more stages (ML-NDT layers s..n, or NDT's single grid); each
// stage but the last runs a fixed number of iterations (Table 3.1: three), the last runs until
// ‖Δξ‖ < ε or the iteration cap. Solvers: Newton (eq. 3.16, H + γI when H is not positive
// definite) with a step control (none: the update as printed; an Armijo line search; the
// Moré–Thuente line search; or a trust region by adaptive damping of H), Levenberg–Marquardt
// (eq. 3.21) and Ceres' LM.
#include <cstddef>
#include <limits>
#include <string>

#include "ndt/ndt_score.hpp"
#include "optim/more_thuente.hpp"
#include "sextant/matchers/optimizer_settings.hpp"
#include "sextant/matchers/registration_result.hpp"

namespace sextant {

/// What the loop optimises. Scores are minimised.
class StagedObjective {
 public:
  virtual ~StagedObjective() = default;
  virtual int stages() const = 0;
  /// Label for traces (the ML-NDT layer number).
  virtual int stage_label(int stage) const = 0;
  virtual ScoreEvaluation evaluate(int stage, const Vector6d& xi, Derivatives derivatives) const = 0;
  /// Ceres and LM need a least-squares form Σ‖Lᵀe‖²: the Mahalanobis grid of the stage, or null.
  virtual const NdtGrid* mahalanobis_grid(int stage) const = 0;
  /// Score of an input point without a Gaussian (included in evaluate()'s score).
  virtual double unmatched_penalty() const { return 0.0; }
  /// τ of the stage: terms with eᵀC⁻¹e > τ are charged τ and contribute no derivatives.
  virtual double max_distance(int /*stage*/) const { return std::numeric_limits<double>::infinity(); }
  virtual const PointCloud& input() const = 0;
  /// Mean of a matched point's score term at the right pose, for the fit check of
  /// registration_quality.hpp (3 for the Mahalanobis score: eᵀC⁻¹e ~ χ²₃); 0: no prediction.
  virtual double predicted_matched_score() const { return 0.0; }
};

/// Runs the stages from `initial`; never throws for bad data (status in the result). Fills T,
/// converged, why, iterations, score, H (exact Hessian at the solution), trace and matched_points.
RegistrationResult optimize(const StagedObjective& objective, const Eigen::Isometry3d& initial,
                            const OptimizerSettings& settings);

}  // namespace sextant
