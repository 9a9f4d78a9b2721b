#include "sextant/eval/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <boost/math/distributions/binomial.hpp>

#include "sextant/core/chi_square.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/small_sample_intervals.hpp"

namespace sextant {
namespace {

Interval undefined(double confidence, std::size_t n = 0) {
  return {kNaN, kNaN, kNaN, confidence, n};
}

/// Two-sided standard-normal quantile z with P(|Z| ≤ z) = confidence.
double two_sided_z(double confidence) {
  return normal_quantile(0.5 + 0.5 * confidence);
}

std::vector<double> finite_values(const std::vector<double>& values) {
  std::vector<double> out;
  out.reserve(values.size());
  for (double v : values)
    if (std::isfinite(v)) out.push_back(v);
  return out;
}

double median_of(std::vector<double>& v) {
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid), v.end());
  const double upper = v[mid];
  if (v.size() % 2 == 1) return upper;
  const double lower = *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid));
  return 0.5 * (lower + upper);
}

double median_copy(std::vector<double> v) {
  return median_of(v);
}

void resample(const std::vector<double>& from, std::vector<double>& into, Rng& rng) {
  into.resize(from.size());
  for (double& v : into) v = from[rng.index(from.size())];
}

std::string number(double v, int precision) {
  if (!std::isfinite(v)) return "nan";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", precision, v);
  return buf;
}

}  // namespace

Interval percentile_interval(double estimate, std::vector<double>& draws, double confidence, std::size_t n) {
  std::sort(draws.begin(), draws.end());
  const double tail = 0.5 * (1.0 - confidence);
  const auto at = [&](double q) {
    const double pos = q * static_cast<double>(draws.size() - 1);
    const auto i = static_cast<std::size_t>(std::floor(pos));
    const std::size_t j = std::min(i + 1, draws.size() - 1);
    return draws[i] + (pos - static_cast<double>(i)) * (draws[j] - draws[i]);
  };
  return {estimate, at(tail), at(1.0 - tail), confidence, n};
}

bool Interval::defined() const {
  return std::isfinite(estimate) && std::isfinite(lo) && std::isfinite(hi);
}

Interval wilson_interval(std::size_t successes, std::size_t n, double confidence) {
  if (n == 0) return undefined(confidence);
  const double z = two_sided_z(confidence);
  const double nn = static_cast<double>(n);
  const double p = static_cast<double>(successes) / nn;
  const double denom = 1.0 + z * z / nn;
  const double centre = (p + z * z / (2.0 * nn)) / denom;
  const double half = z * std::sqrt(p * (1.0 - p) / nn + z * z / (4.0 * nn * nn)) / denom;
  return {p, std::max(0.0, centre - half), std::min(1.0, centre + half), confidence, n};
}

Interval mean_interval(const std::vector<double>& values, double confidence) {
  return t_mean_interval(values, confidence);
}

Interval bootstrap_median(const std::vector<double>& values, std::uint64_t seed, double confidence,
                          int resamples) {
  const std::vector<double> v = finite_values(values);
  if (v.size() < kSmallSample) return median_interval(v, confidence);
  if (resamples < 1) return undefined(confidence, v.size());
  Rng rng(seed);
  std::vector<double> draws, sample;
  draws.reserve(static_cast<std::size_t>(resamples));
  for (int b = 0; b < resamples; ++b) {
    resample(v, sample, rng);
    draws.push_back(median_of(sample));
  }
  return percentile_interval(median_copy(v), draws, confidence, v.size());
}

Interval bootstrap_ratio_of_medians(const std::vector<double>& numerator,
                                    const std::vector<double>& denominator, std::uint64_t seed,
                                    double confidence, int resamples) {
  const std::vector<double> a = finite_values(numerator), b = finite_values(denominator);
  if (std::min(a.size(), b.size()) < kSmallSample) return ratio_of_medians_interval(a, b, confidence);
  if (resamples < 1) return undefined(confidence, std::min(a.size(), b.size()));
  Rng rng(seed);
  std::vector<double> draws, sa, sb;
  draws.reserve(static_cast<std::size_t>(resamples));
  for (int k = 0; k < resamples; ++k) {
    resample(a, sa, rng);
    resample(b, sb, rng);
    draws.push_back(median_of(sa) / median_of(sb));
  }
  return percentile_interval(median_copy(a) / median_copy(b), draws, confidence,
                             std::min(a.size(), b.size()));
}

Interval bootstrap_paired_mean_difference(const std::vector<double>& a, const std::vector<double>& b,
                                          std::uint64_t seed, double confidence, int resamples) {
  std::vector<double> d;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    if (std::isfinite(a[i]) && std::isfinite(b[i])) d.push_back(a[i] - b[i]);
  if (d.size() < kSmallSample) return t_mean_interval(d, confidence);
  if (resamples < 1) return undefined(confidence, d.size());
  const auto mean = [](const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
  };
  Rng rng(seed);
  std::vector<double> draws, sample;
  draws.reserve(static_cast<std::size_t>(resamples));
  for (int k = 0; k < resamples; ++k) {
    resample(d, sample, rng);
    draws.push_back(mean(sample));
  }
  return percentile_interval(mean(d), draws, confidence, d.size());
}

double mcnemar_p_value(std::size_t only_a, std::size_t only_b) {
  const std::size_t n = only_a + only_b;
  if (n == 0) return 1.0;
  const std::size_t k = std::min(only_a, only_b);
  // 2 · P(X ≤ k) for X ~ Binomial(n, 1/2) (Boost.Math).
  const boost::math::binomial_distribution<double> x(static_cast<double>(n), 0.5);
  return std::min(1.0, 2.0 * boost::math::cdf(x, static_cast<double>(k)));
}

PairedRates compare_paired_successes(const std::vector<bool>& a, const std::vector<bool>& b,
                                     double confidence) {
  PairedRates r;
  r.n = std::min(a.size(), b.size());
  std::size_t both = 0, neither = 0;
  for (std::size_t i = 0; i < r.n; ++i) {
    r.a_successes += a[i];
    r.b_successes += b[i];
    both += a[i] && b[i];
    neither += !a[i] && !b[i];
    r.only_a += a[i] && !b[i];
    r.only_b += !a[i] && b[i];
  }
  r.p_value = mcnemar_p_value(r.only_a, r.only_b);
  if (r.n == 0) {
    r.difference = undefined(confidence);
    return r;
  }
  // Newcombe (1998), method 10: Wilson intervals of both marginals, corrected for their correlation.
  const Interval w1 = wilson_interval(r.a_successes, r.n, confidence);
  const Interval w2 = wilson_interval(r.b_successes, r.n, confidence);
  const double a1 = static_cast<double>(both), b1 = static_cast<double>(r.only_a);
  const double c1 = static_cast<double>(r.only_b), d1 = static_cast<double>(neither);
  const double denom = (a1 + b1) * (c1 + d1) * (a1 + c1) * (b1 + d1);
  const double phi = denom > 0.0 ? (a1 * d1 - b1 * c1) / std::sqrt(denom) : 0.0;
  const double p1 = w1.estimate, p2 = w2.estimate;
  const double delta =
      std::sqrt(std::max(0.0, (p1 - w1.lo) * (p1 - w1.lo) - 2.0 * phi * (p1 - w1.lo) * (w2.hi - p2) +
                                  (w2.hi - p2) * (w2.hi - p2)));
  const double epsilon =
      std::sqrt(std::max(0.0, (w1.hi - p1) * (w1.hi - p1) - 2.0 * phi * (w1.hi - p1) * (p2 - w2.lo) +
                                  (p2 - w2.lo) * (p2 - w2.lo)));
  r.difference = {p1 - p2, std::max(-1.0, p1 - p2 - delta), std::min(1.0, p1 - p2 + epsilon), confidence,
                  r.n};
  return r;
}

NormalityTest jarque_bera(const std::vector<double>& values) {
  const std::vector<double> v = finite_values(values);
  NormalityTest t;
  t.n = v.size();
  if (v.size() < 3) return t;
  const double n = static_cast<double>(v.size());
  double mean = 0.0;
  for (double x : v) mean += x;
  mean /= n;
  double m2 = 0.0, m3 = 0.0, m4 = 0.0;
  for (double x : v) {
    const double d = x - mean;
    m2 += d * d;
    m3 += d * d * d;
    m4 += d * d * d * d;
  }
  m2 /= n;
  m3 /= n;
  m4 /= n;
  if (m2 <= 0.0) return t;
  t.skewness = m3 / std::pow(m2, 1.5);
  t.excess_kurtosis = m4 / (m2 * m2) - 3.0;
  t.statistic = n / 6.0 * (t.skewness * t.skewness + 0.25 * t.excess_kurtosis * t.excess_kurtosis);
  t.p_value = std::exp(-0.5 * t.statistic);  // survival function of χ²(2)
  return t;
}

Verdict verdict_greater(const Interval& interval, double threshold) {
  if (!interval.defined()) return Verdict::not_comparable;
  if (interval.lo > threshold) return Verdict::holds;
  if (interval.hi <= threshold) return Verdict::does_not_hold;
  return Verdict::inconclusive;
}

Verdict verdict_less(const Interval& interval, double threshold) {
  if (!interval.defined()) return Verdict::not_comparable;
  if (interval.hi < threshold) return Verdict::holds;
  if (interval.lo >= threshold) return Verdict::does_not_hold;
  return Verdict::inconclusive;
}

Verdict verdict_in_band(const Interval& interval, double band_lo, double band_hi) {
  if (!interval.defined()) return Verdict::not_comparable;
  if (interval.lo >= band_lo && interval.hi <= band_hi) return Verdict::holds;
  if (interval.hi < band_lo || interval.lo > band_hi) return Verdict::does_not_hold;
  return Verdict::inconclusive;
}

Verdict verdict_all(const std::vector<Verdict>& verdicts) {
  if (verdicts.empty()) return Verdict::not_comparable;
  for (Verdict order : {Verdict::not_comparable, Verdict::does_not_hold, Verdict::inconclusive})
    if (std::find(verdicts.begin(), verdicts.end(), order) != verdicts.end()) return order;
  return Verdict::holds;
}

std::string describe(const Interval& interval, const std::string& unit, int precision) {
  if (!interval.defined()) return "no data (n = " + std::to_string(interval.n) + ")";
  return number(interval.estimate, precision) + unit + " [" + number(interval.lo, precision) + unit + ", " +
         number(interval.hi, precision) + unit + "] (" + number(100.0 * interval.confidence, 0) +
         " %, n = " + std::to_string(interval.n) + ")";
}

std::string describe(const PairedRates& rates, int precision) {
  std::string text = "a " + std::to_string(rates.a_successes) + "/" + std::to_string(rates.n) + " vs b " +
                     std::to_string(rates.b_successes) + "/" + std::to_string(rates.n);
  if (rates.difference.defined()) {
    text += ", difference " + std::string(rates.difference.estimate >= 0 ? "+" : "") +
            number(rates.difference.estimate, precision) + " [" + number(rates.difference.lo, precision) +
            ", " + number(rates.difference.hi, precision) + "]";
  }
  char p[32];
  std::snprintf(p, sizeof p, "%.3g", rates.p_value);
  return text + ", McNemar p = " + p;
}

}  // namespace sextant
