#pragma once
// The statistics behind a claim's verdict. A verdict is decided on an interval, never on a bare
// comparison of two numbers: a claim holds when the whole interval supports it, does not hold when
// the whole interval contradicts it, and is inconclusive when the interval straddles the claim.
//
//   // "ML-NDT succeeds more often than NDT" on the same pairs (paired binary outcomes):
//   const PairedRates r = compare_paired_successes(mlndt_ok, ndt_ok);
//   Claim c{"ML-NDT succeeds more often than NDT", verdict_greater(r.difference, 0.0), describe(r)};
//
//   // "ML-NDT is about 4× faster" with the band the report accepts as "about 4×":
//   const Interval speedup = bootstrap_ratio_of_medians(ndt_seconds, mlndt_seconds, seed);
//   Claim f{"ML-NDT is about 4× faster than NDT", verdict_in_band(speedup, 2.0, 8.0), describe(speedup,
//   "×")};
//
// Every resampling draws from an Rng seeded by the caller, so verdicts are deterministic.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sextant/eval/html_report.hpp"

namespace sextant {

/// A point estimate with a confidence interval; all NaN when undefined (e.g. no data).
struct Interval {
  double estimate;
  double lo;
  double hi;
  double confidence = 0.95;
  std::size_t n = 0;  ///< sample size behind the interval (pairs, runs, ...)

  bool defined() const;
};

// --- intervals ----------------------------------------------------------------------------------

/// The percentile interval of bootstrap `draws` (sorted in place, non-empty) around `estimate`.
Interval percentile_interval(double estimate, std::vector<double>& draws, double confidence, std::size_t n);
/// Wilson score interval of a proportion k / n (estimate k / n; NaN for n = 0).
Interval wilson_interval(std::size_t successes, std::size_t n, double confidence = 0.95);
/// Mean with the Student-t interval (mean ± t_{n−1}·s/√n, t_mean_interval); NaN for fewer than 2
/// finite values.
Interval mean_interval(const std::vector<double>& values, double confidence = 0.95);
// Below kSmallSample (20) observations the three bootstraps below use the intervals of
// small_sample_intervals.hpp instead, whose stated confidence they have (the order-statistic median
// interval, the Student-t mean): a percentile bootstrap of 3–19 values covers less than it says.
/// Percentile bootstrap of the median of the finite values.
Interval bootstrap_median(const std::vector<double>& values, std::uint64_t seed, double confidence = 0.95,
                          int resamples = 2000);
/// Percentile bootstrap of median(numerator) / median(denominator), the two samples resampled
/// independently (e.g. run times of two methods). NaN when either has no finite value.
Interval bootstrap_ratio_of_medians(const std::vector<double>& numerator,
                                    const std::vector<double>& denominator, std::uint64_t seed,
                                    double confidence = 0.95, int resamples = 2000);
/// Percentile bootstrap of the mean of a − b over the pairs where both are finite (paired samples).
Interval bootstrap_paired_mean_difference(const std::vector<double>& a, const std::vector<double>& b,
                                          std::uint64_t seed, double confidence = 0.95, int resamples = 2000);

// --- tests --------------------------------------------------------------------------------------

/// Paired success/failure outcomes of two methods on the same cases.
struct PairedRates {
  std::size_t n = 0;  ///< pairs compared
  std::size_t a_successes = 0, b_successes = 0;
  std::size_t only_a = 0, only_b = 0;  ///< discordant pairs
  double p_value = 1.0;                ///< exact two-sided McNemar (binomial on the discordant pairs)
  Interval difference{};               ///< rate(a) − rate(b), Newcombe's interval for paired data
};

/// Compares a[i] against b[i] for i < min(size); NaN-free by construction.
PairedRates compare_paired_successes(const std::vector<bool>& a, const std::vector<bool>& b,
                                     double confidence = 0.95);
/// Exact two-sided McNemar p-value from the discordant counts.
double mcnemar_p_value(std::size_t only_a, std::size_t only_b);

/// Jarque–Bera normality test of the finite values: statistic and p-value (χ² with 2 dof).
struct NormalityTest {
  std::size_t n = 0;
  double skewness = 0.0, excess_kurtosis = 0.0;
  double statistic = 0.0;
  double p_value = 1.0;
};
NormalityTest jarque_bera(const std::vector<double>& values);

// --- verdicts -----------------------------------------------------------------------------------

/// holds if lo > threshold, does not hold if hi ≤ threshold, inconclusive otherwise;
/// not comparable when the interval is undefined.
Verdict verdict_greater(const Interval& interval, double threshold);
/// holds if hi < threshold, does not hold if lo ≥ threshold, inconclusive otherwise.
Verdict verdict_less(const Interval& interval, double threshold);
/// A magnitude claim ("about 4×"): holds if [lo, hi] ⊂ [band_lo, band_hi], does not hold if the two
/// do not overlap, inconclusive otherwise.
Verdict verdict_in_band(const Interval& interval, double band_lo, double band_hi);
/// All of several verdicts: not comparable if any is, else does not hold if any does not, else
/// inconclusive if any is, else holds.
Verdict verdict_all(const std::vector<Verdict>& verdicts);

/// "0.42 [0.31, 0.55] (95 %, n = 100)" with `unit` appended to the numbers ("", "×", " cm").
std::string describe(const Interval& interval, const std::string& unit = "", int precision = 2);
/// "a 97/100 vs b 88/100, difference +0.09 [0.03, 0.16], McNemar p = 0.004".
std::string describe(const PairedRates& rates, int precision = 2);

}  // namespace sextant
