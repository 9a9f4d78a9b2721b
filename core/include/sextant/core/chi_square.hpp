#pragma once
// The χ² distribution, for consistency bounds (NEES, NIS) and association gates, and the normal
// quantile of the confidence intervals (eval/verdict.hpp):
//
//   const double gate = chi_square_quantile(0.999, 4);   // 18.467
//   if (nis > gate) reject();
//
// Both come from Boost.Math's chi_squared_distribution (the regularised incomplete gamma function
// P(k/2, x/2) and its inverse, to double precision); these functions keep the argument checks.

namespace sextant {

/// P(X ≤ x) for X ~ χ²(dof); dof > 0, x ≥ 0 (x ≤ 0 gives 0).
double chi_square_cdf(double x, double dof);

/// The x with chi_square_cdf(x, dof) = p, for 0 < p < 1 and dof > 0. Throws std::invalid_argument
/// outside that range.
double chi_square_quantile(double p, double dof);

/// The standard-normal quantile Φ⁻¹(p) (Boost.Math), for 0 < p < 1: 1.959964 at p = 0.975. Throws
/// std::invalid_argument outside that range.
double normal_quantile(double p);

}  // namespace sextant
