#pragma once
// The χ² distribution, for consistency bounds (NEES, NIS) and association gates:
//
//   const double gate = chi_square_quantile(0.999, 4);   // 18.467
//   if (nis > gate) reject();
//
// The CDF is the regularised lower incomplete gamma function P(k/2, x/2), evaluated by its power
// series for x < a + 1 and by the Legendre continued fraction (modified Lentz) otherwise; the
// quantile inverts it by bisection on a bracket. Accurate to ~1e-12 relative for k ≤ 1000.

namespace sextant {

/// P(X ≤ x) for X ~ χ²(dof); dof > 0, x ≥ 0 (x ≤ 0 gives 0).
double chi_square_cdf(double x, double dof);

/// The x with chi_square_cdf(x, dof) = p, for 0 < p < 1 and dof > 0. Throws std::invalid_argument
/// outside that range.
double chi_square_quantile(double p, double dof);

}  // namespace sextant
