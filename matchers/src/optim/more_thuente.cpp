// The Moré–Thuente line search (Moré & Thuente 1994), written from the paper's §§2–4.
#include "optim/more_thuente.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sextant {

namespace {

constexpr double kShrink = 0.66;          // δ of §4 (case 3) and of the bisection safeguard of §2
constexpr double kExtrapolateMin = 1.1;   // unbracketed trials lie in α_t + [1.1, 4]·(α_t − α_l)
constexpr double kExtrapolateMax = 4.0;   // (the factors of the authors' MINPACK-2 code)
constexpr double kRelativeWidth = 1e-12;  // interval width below which rounding decides

/// A point of the search: α, the function (ψ or φ) and its derivative there.
struct MtPoint {
  double a = 0.0, f = 0.0, g = 0.0;
};

/// Minimiser of the cubic through (a, f_a, g_a) and (b, f_b, g_b); false when the cubic has no
/// local minimiser (d₁² < g_a·g_b) or the numbers are not finite. With d₁ = g_a + g_b − 3(f_a − f_b)/(a − b),
/// d₂ = sign(b − a)·√(d₁² − g_a·g_b): α_c = b − (b − a)(g_b + d₂ − d₁)/(g_b − g_a + 2d₂).
bool cubic_minimiser(const MtPoint& a, const MtPoint& b, double& out) {
  const double d1 = a.g + b.g - 3.0 * (a.f - b.f) / (a.a - b.a);
  const double discriminant = d1 * d1 - a.g * b.g;
  if (!(discriminant >= 0.0)) return false;
  const double d2 = std::copysign(std::sqrt(discriminant), b.a - a.a);
  const double denominator = b.g - a.g + 2.0 * d2;
  if (denominator == 0.0) return false;
  out = b.a - (b.a - a.a) * (b.g + d2 - d1) / denominator;
  return std::isfinite(out);
}

/// Minimiser of the quadratic through f_a, g_a at a and f_b at b (§4, α_q).
double quadratic_minimiser(const MtPoint& a, const MtPoint& b) {
  return a.a + 0.5 * (b.a - a.a) * a.g / ((a.f - b.f) / (b.a - a.a) + a.g);
}

/// Zero of the line through the derivatives g_a at a and g_b at b (§4, the secant step α_s).
double secant(const MtPoint& a, const MtPoint& b) {
  return a.a + (b.a - a.a) * a.g / (a.g - b.g);
}

/// The trial value selection of §4 from the interval's ends l (the lowest f so far), u and the
/// trial t just evaluated; sets `bracketed` when t proves a minimiser lies between l and t.
/// [lo, hi] bounds the extrapolating choices of cases 3 and 4 while nothing is bracketed.
double choose_trial(const MtPoint& l, const MtPoint& t, const MtPoint& u, bool& bracketed, double lo,
                    double hi) {
  if (t.f > l.f) {  // case 1: a higher value; the minimiser lies between l and t
    bracketed = true;
    const double q = quadratic_minimiser(l, t);
    double c = q;
    if (!cubic_minimiser(l, t, c)) c = q;
    return std::abs(c - l.a) < std::abs(q - l.a) ? c : 0.5 * (q + c);
  }
  if (t.g * l.g < 0.0) {  // case 2: the derivatives change sign between l and t
    bracketed = true;
    const double s = secant(l, t);
    double c = s;
    if (!cubic_minimiser(l, t, c)) c = s;
    return std::abs(c - t.a) >= std::abs(s - t.a) ? c : s;
  }
  const double away = t.a > l.a ? hi : lo;  // the far end in the direction of the step
  if (std::abs(t.g) <= std::abs(l.g)) {     // case 3: lower value, the slope shrinks in magnitude
    // The cubic only when its minimiser lies beyond t; otherwise the far end.
    double c = away;
    if (!cubic_minimiser(l, t, c) || (c - t.a) * (t.a - l.a) <= 0.0) c = away;
    const double s = t.g != l.g ? secant(l, t) : away;
    if (!bracketed) return std::clamp(std::abs(c - t.a) > std::abs(s - t.a) ? c : s, lo, hi);
    const double next = std::abs(c - t.a) < std::abs(s - t.a) ? c : s;
    const double limit = t.a + kShrink * (u.a - t.a);  // stay well inside [t, u]
    return t.a > l.a ? std::min(limit, next) : std::max(limit, next);
  }
  // case 4: lower value, the slope grows in magnitude: the cubic through t and u, or the far end
  if (!bracketed) return away;
  double c = 0.5 * (t.a + u.a);
  if (!cubic_minimiser(t, u, c)) c = 0.5 * (t.a + u.a);
  return c;
}

}  // namespace

bool MoreThuenteSettings::valid(std::string* why) const {
  const char* problem = nullptr;
  if (!(mu > 0.0 && mu < 1.0))
    problem = "line_search_mu (sufficient decrease μ) must lie in (0, 1)";
  else if (!(eta >= mu && eta < 1.0))
    problem = "line_search_eta (curvature η) must lie in [μ, 1)";
  else if (!(max_step > 0.0 && max_step <= 1000.0))
    problem = "line_search_max_step must lie in (0, 1000] (ξ units: m and rad)";
  else if (iterations < 1 || iterations > 100)
    problem = "line_search_iterations must lie in [1, 100]";
  if (problem && why) *why = problem;
  return problem == nullptr;
}

bool strong_wolfe(const LineSearchSample& origin, double step, const LineSearchSample& at, double mu,
                  double eta) {
  return at.value <= origin.value + mu * step * origin.slope &&  // eq. (1.1)
         std::abs(at.slope) <= eta * std::abs(origin.slope);     // eq. (1.2)
}

LineSearchResult more_thuente(const std::function<LineSearchSample(double)>& phi,
                              const LineSearchSample& origin, double initial, double step_min,
                              double step_max, const MoreThuenteSettings& settings) {
  LineSearchResult result;
  result.at = origin;
  if (!(origin.slope < 0.0) || !std::isfinite(origin.value) || !(step_max > step_min)) {
    result.end = LineSearchEnd::kNotDescent;
    return result;
  }
  const double f0 = origin.value, g0 = origin.slope, mu = settings.mu;
  // ψ(α) = φ(α) − φ(0) − μ·φ'(0)·α (§2) while `auxiliary`; φ itself after the switch of §3.
  bool auxiliary = true;
  const auto as_point = [&](double a, double value, double slope) {
    return auxiliary ? MtPoint{a, value - f0 - mu * g0 * a, slope - mu * g0} : MtPoint{a, value, slope};
  };
  // The interval's ends in φ terms: l has the lowest value found; I₀ = [0, ∞] (§2).
  struct End {
    double a;
    LineSearchSample s;
  };
  End l{0.0, origin}, u{0.0, origin};
  bool bracketed = false;
  double width = step_max - step_min, width_before = 2.0 * width;
  double alpha = std::clamp(initial, step_min, step_max);
  for (int k = 0; k < settings.iterations; ++k) {
    const LineSearchSample at = phi(alpha);
    ++result.evaluations;
    if (!at.ok || !std::isfinite(at.value) || !std::isfinite(at.slope)) {
      // No value: too long a step. It closes the interval; bisect towards α_l.
      u = End{alpha, LineSearchSample{std::numeric_limits<double>::infinity(), 0.0, false}};
      bracketed = true;
      alpha = 0.5 * (l.a + alpha);
      continue;
    }
    const double psi = at.value - f0 - mu * g0 * alpha;
    const double dpsi = at.slope - mu * g0;
    const auto stop = [&](LineSearchEnd end) {
      result.step = alpha;
      result.at = at;
      result.end = end;
      return result;
    };
    if (psi <= 0.0 && std::abs(at.slope) <= settings.eta * std::abs(g0))
      return stop(LineSearchEnd::kStrongWolfe);
    if (alpha == step_max && psi <= 0.0 && dpsi < 0.0) return stop(LineSearchEnd::kAtMaxStep);
    if (alpha == step_min && (psi > 0.0 || dpsi >= 0.0)) return stop(LineSearchEnd::kAtMinStep);
    if (auxiliary && psi <= 0.0 && at.slope > 0.0) auxiliary = false;  // §3: from here on φ

    const MtPoint L = as_point(l.a, l.s.value, l.s.slope), T = as_point(alpha, at.value, at.slope);
    const MtPoint U = u.s.ok ? as_point(u.a, u.s.value, u.s.slope) : MtPoint{u.a, u.s.value, 0.0};
    double lo = step_min, hi = step_max;
    if (!bracketed) {  // extrapolation bounds beyond α_t
      lo = std::max(step_min, alpha + kExtrapolateMin * (alpha - l.a));
      hi = std::min(step_max, alpha + kExtrapolateMax * (alpha - l.a));
      if (lo > hi) lo = hi;
    }
    double next = choose_trial(L, T, U, bracketed, lo, hi);
    // The updating algorithm of §2 (U1–U3) on the same function.
    if (T.f > L.f) {
      u = End{alpha, at};  // U1
    } else {
      if (T.g * (L.a - T.a) < 0.0) u = l;  // U3 (U2 keeps u)
      l = End{alpha, at};
    }
    if (bracketed) {
      const double size = std::abs(u.a - l.a);
      if (size <= kRelativeWidth * std::max(std::abs(l.a), std::abs(u.a))) break;
      if (size >= kShrink * width_before) next = l.a + 0.5 * (u.a - l.a);  // §2: too slow → bisect
      width_before = width;
      width = size;
      next = std::clamp(next, std::min(l.a, u.a), std::max(l.a, u.a));
    }
    alpha = std::clamp(next, step_min, step_max);
  }
  result.step = l.a;  // the lowest value found (φ(0) when nothing decreased)
  result.at = l.s;
  result.end =
      result.evaluations < settings.iterations ? LineSearchEnd::kIntervalTiny : LineSearchEnd::kIterations;
  return result;
}

}  // namespace sextant
