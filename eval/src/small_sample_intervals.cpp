#include "sextant/eval/small_sample_intervals.hpp"

#include <algorithm>
#include <cmath>

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/students_t.hpp>

#include "sextant/core/units.hpp"

namespace sextant {
namespace {

std::vector<double> finite_sorted(const std::vector<double>& values) {
  std::vector<double> v;
  for (double x : values)
    if (std::isfinite(x)) v.push_back(x);
  std::sort(v.begin(), v.end());
  return v;
}

double sorted_median(const std::vector<double>& v) {
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

double order_statistic_coverage(std::size_t n, std::size_t j) {
  if (n == 0 || 2 * j + 1 > n) return 0.0;
  // The median is missed when at most j values fall below it, or at most j above: 1 − 2·P(X ≤ j),
  // X ~ Binomial(n, ½) (Boost.Math).
  const boost::math::binomial_distribution<double> x(static_cast<double>(n), 0.5);
  return std::max(0.0, 1.0 - 2.0 * boost::math::cdf(x, static_cast<double>(j)));
}

Interval median_interval(const std::vector<double>& values, double confidence) {
  const std::vector<double> v = finite_sorted(values);
  const std::size_t n = v.size();
  if (n == 0) return {kNaN, kNaN, kNaN, confidence, 0};
  // The largest j (narrowest interval) whose coverage still reaches the confidence; j = 0 is [min, max].
  std::size_t j = 0;
  while (order_statistic_coverage(n, j + 1) >= confidence) ++j;
  const double coverage = order_statistic_coverage(n, j);
  return {sorted_median(v), v[j], v[n - 1 - j], coverage, n};
}

Interval t_mean_interval(const std::vector<double>& values, double confidence) {
  const std::vector<double> v = finite_sorted(values);
  const std::size_t n = v.size();
  if (n < 2) return {kNaN, kNaN, kNaN, confidence, n};
  double mean = 0.0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(n);
  double ss = 0.0;
  for (double x : v) ss += (x - mean) * (x - mean);
  const double se = std::sqrt(ss / static_cast<double>(n - 1) / static_cast<double>(n));
  const boost::math::students_t t(static_cast<double>(n - 1));
  const double q = boost::math::quantile(boost::math::complement(t, 0.5 * (1.0 - confidence)));
  return {mean, mean - q * se, mean + q * se, confidence, n};
}

Interval paired_ratio_interval(const std::vector<double>& a, const std::vector<double>& b,
                               double confidence) {
  std::vector<double> ratios;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    if (std::isfinite(a[i]) && std::isfinite(b[i]) && b[i] > 0.0) ratios.push_back(a[i] / b[i]);
  return median_interval(ratios, confidence);
}

Interval ratio_of_medians_interval(const std::vector<double>& a, const std::vector<double>& b,
                                   double confidence) {
  const double each = 1.0 - 0.5 * (1.0 - confidence);
  const Interval ma = median_interval(a, each), mb = median_interval(b, each);
  const std::size_t n = std::min(ma.n, mb.n);
  if (!ma.defined() || !mb.defined() || mb.lo <= 0.0 || ma.lo < 0.0) return {kNaN, kNaN, kNaN, confidence, n};
  const double joint = std::max(0.0, 1.0 - (1.0 - ma.confidence) - (1.0 - mb.confidence));
  return {ma.estimate / mb.estimate, ma.lo / mb.hi, ma.hi / mb.lo, joint, n};
}

}  // namespace sextant
