#include "sextant/core/chi_square.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace sextant {
namespace {

constexpr double kTolerance = 1e-15;
constexpr int kMaxTerms = 100000;

/// P(a, x) by the series e^(−x) x^a / Γ(a+1) · Σ xⁿ / ((a+1)…(a+n)), for x < a + 1.
double lower_gamma_series(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < kMaxTerms; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * kTolerance) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

/// Q(a, x) = 1 − P(a, x) by the continued fraction 1/(x+1−a− 1·(1−a)/(x+3−a− …)), for x ≥ a + 1.
double upper_gamma_fraction(double a, double x) {
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
  for (int n = 1; n < kMaxTerms; ++n) {
    const double an = -n * (n - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < kTolerance) break;
  }
  return h * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

}  // namespace

double chi_square_cdf(double x, double dof) {
  if (!(dof > 0.0)) throw std::invalid_argument("chi_square_cdf: dof must be > 0");
  if (!(x > 0.0)) return 0.0;
  if (std::isinf(x)) return 1.0;
  const double a = 0.5 * dof, half = 0.5 * x;
  return half < a + 1.0 ? lower_gamma_series(a, half) : 1.0 - upper_gamma_fraction(a, half);
}

double chi_square_quantile(double p, double dof) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("chi_square_quantile: p must lie in (0, 1)");
  if (!(dof > 0.0) || std::isinf(dof)) throw std::invalid_argument("chi_square_quantile: dof must be > 0");
  double lo = 0.0, hi = dof + 10.0 * std::sqrt(2.0 * dof) + 10.0;
  while (chi_square_cdf(hi, dof) < p) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-13 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (chi_square_cdf(mid, dof) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace sextant
