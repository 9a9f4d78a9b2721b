#pragma once
// The optimiser's settings (the loop itself is private: matchers/src/optim/optimizer.hpp): the solver,
// the Newton step control and its Moré–Thuente line search, the iteration schedule (Table 3.1) and the
// free parameters.
#include <cstddef>
#include <string>

#include "sextant/core/enum_names.hpp"
#include "sextant/matchers/dof_mask.hpp"

namespace sextant {

/// The Moré–Thuente line search (Moré and Thuente 1994): eqs. (1.1)–(1.2) of the paper.
struct MoreThuenteSettings {
  double mu = 1e-4;  ///< μ of eq. (1.1), sufficient decrease, in (0, 1) [1]
  double eta = 0.9;  ///< η of eq. (1.2), curvature, in [μ, 1) [1]
  double max_step = 1.0;  ///< NDT: the longest step ‖α·Δξ‖, in ξ's mixed units [m and rad, as ε], ≤ 1000
  int iterations = 10;  ///< evaluations of φ per line search, in [1, 100] [count]
  bool valid(std::string* why) const;
};

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

}  // namespace sextant
