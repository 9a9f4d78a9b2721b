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

#include "sextant/core/enum_names.hpp"
#include "sextant/matchers/dof_mask.hpp"
#include "sextant/matchers/more_thuente.hpp"
#include "sextant/matchers/ndt_score.hpp"
#include "sextant/matchers/registration_result.hpp"

namespace sextant {

enum class SolverKind { kNewton, kLevenbergMarquardt, kCeres };

/// How a Newton step is controlled:
///   none         — Δ of eq. (3.16) (H + γI) taken in full, as the thesis prints it;
///   line_search  — backtracking (Armijo) along Δ: halve until the score drops enough;
///   more_thuente — the Moré–Thuente (1994) line search along Δ, as Magnusson's thesis (2009, [32]) runs
///                  NDT: a step α·Δ meeting the strong Wolfe conditions, α ∈ [0, α_max] with
///                  α_max = line_search_max_step / ‖Δ‖, first trial α = min(1, α_max)
///                  (more_thuente.hpp);
///   trust_region — (H + γI + λ·d̄·I)Δ = −g with λ adapted like LM's (÷10 after a step that lowers
///                  the score, ×10 and retry otherwise; d̄ = mean |diag H|), λ₀ = 0 (a full Newton
///                  step is tried first);
///   trust_region_last — the trust region in the last stage only; the coarser stages (three
///                  iterations each) take the full step, whose reach gives ML-NDT its capture range
///                  (a monotone step control there loses a 3 m / 15° offset that the full steps
///                  recover: Mlndt.LongRangeBeatsFixedCellNdt).
enum class StepControl { kNone, kLineSearch, kMoreThuente, kTrustRegion, kTrustRegionLast };

inline constexpr EnumNames<StepControl, 5> kStepControlNames{
    "step control",
    {{{StepControl::kNone, "none"},
      {StepControl::kLineSearch, "line_search"},
      {StepControl::kMoreThuente, "more_thuente"},
      {StepControl::kTrustRegion, "trust_region"},
      {StepControl::kTrustRegionLast, "trust_region_last"}}}};
bool from_string(const std::string& text, StepControl* out);
std::string to_string(StepControl control);

inline constexpr EnumNames<SolverKind, 3> kSolverNames{"solver",
                                                       {{{SolverKind::kNewton, "newton"},
                                                         {SolverKind::kLevenbergMarquardt, "lm"},
                                                         {SolverKind::kCeres, "ceres"}}}};
bool from_string(const std::string& text, SolverKind* out);
std::string to_string(SolverKind kind);

struct OptimizerSettings {
  SolverKind solver = SolverKind::kNewton;
  int iterations_per_stage = 3;  ///< iterations in every stage but the last (Table 3.1) [count]
  int max_iterations = 100;      ///< cap on all iterations [count]
  double epsilon = 1e-4;  ///< stop in the last stage when ‖Δξ‖ < ε [m and rad mixed, as eq. 3.12]
  /// LM: a stage is at its minimum when the damped step's predicted decrease of the score (the
  /// Gauss–Newton model, −gᵀΔ − ΔᵀJᵀJΔ) is below this × the score, and the step is not tried. At
  /// 10⁻⁵ that is about a millimetre of motion at the last layer (docs/matcher_defaults.md, "Fewer
  /// evaluations") [ratio, 0..1; 0: off, the thesis' ε alone]
  double function_tolerance = 0.0;
  StepControl step_control = StepControl::kNone;  ///< Newton only (LM and Ceres damp themselves)
  std::size_t min_matched = 6;      ///< fewer matched points → too_few_correspondences [count]
  MoreThuenteSettings line_search;  ///< μ, η, step bound and budget of step_control more_thuente
  DofMask dof;
  bool valid(std::string* why) const;
};

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
