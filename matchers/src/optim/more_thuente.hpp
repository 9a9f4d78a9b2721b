#pragma once
// The line search of Moré & Thuente (1994), "Line search algorithms with guaranteed sufficient
// decrease", ACM TOMS 20(3): on φ(α) = f(x + α·p) with φ'(0) < 0 it looks in [α_min, α_max] for a
// step that satisfies the strong Wolfe conditions
//   φ(α) ≤ φ(0) + μ·α·φ'(0)        (sufficient decrease, eq. 1.1)
//   |φ'(α)| ≤ η·|φ'(0)|            (curvature, eq. 1.2)
// by keeping an interval I = [α_l, α_u] that contains such steps (the updating algorithm of §2 on
// ψ(α) = φ(α) − φ(0) − μ·α·φ'(0), then of §3 on φ itself) and choosing each trial by the cubic,
// quadratic and secant interpolations of §4. Magnusson's thesis (2009; the thesis' ref. [32]) runs NDT's
// Newton steps through it; that is the `more_thuente` step control of optimizer.hpp.
#include <functional>
#include <string>

#include "sextant/matchers/optimizer_settings.hpp"

namespace sextant {

/// φ and φ' at one step; ok = false when φ cannot be evaluated there (the search then treats the
/// step as too long: it becomes the upper end of the interval and the next trial bisects).
struct LineSearchSample {
  double value = 0.0;  ///< φ(α)
  double slope = 0.0;  ///< φ'(α)
  bool ok = true;
};

enum class LineSearchEnd {
  kStrongWolfe,   ///< eqs. (1.1) and (1.2) hold at the step
  kAtMaxStep,     ///< α = α_max with ψ(α_max) ≤ 0 and ψ'(α_max) < 0 (no better step in range)
  kAtMinStep,     ///< α = α_min with ψ(α_min) > 0 or ψ'(α_min) ≥ 0
  kIntervalTiny,  ///< the interval shrank to rounding: the best step found
  kIterations,    ///< the evaluation budget ran out: the best step found (α_l)
  kNotDescent,    ///< φ'(0) ≥ 0: α = 0
};

struct LineSearchResult {
  double step = 0.0;    ///< α
  LineSearchSample at;  ///< φ and φ' at α
  int evaluations = 0;  ///< calls of φ
  LineSearchEnd end = LineSearchEnd::kIterations;
};

/// Searches α ∈ [step_min, step_max] (0 ≤ step_min < step_max) from the trial `initial`, calling
/// `phi` at most `settings.iterations` times. `origin` is φ(0), φ'(0). The step returned never has
/// a larger φ than φ(0); when no trial decreased φ it is α_l = step_min's side (0 for step_min = 0).
LineSearchResult more_thuente(const std::function<LineSearchSample(double)>& phi,
                              const LineSearchSample& origin, double initial, double step_min,
                              double step_max, const MoreThuenteSettings& settings);

/// True when α with φ, φ' = `at` meets eqs. (1.1) and (1.2) for `origin` = φ(0), φ'(0).
bool strong_wolfe(const LineSearchSample& origin, double step, const LineSearchSample& at, double mu,
                  double eta);

}  // namespace sextant
