#pragma once
// Intervals whose coverage holds at the sample sizes the experiments have (3–20 runs), where a
// percentile bootstrap covers less than it says (on n = 3 its "95 %" interval is the middle of at
// most 10 distinct resample means). Each states the confidence it has:
//   - median_interval: the distribution-free interval between two order statistics; its coverage is
//     exact, from Binomial(n, ½), and the reported confidence is that coverage (≥ the requested one
//     when n allows it; for n < 6 even [min, max] has less than 95 %: 1 − 2^{1−n}, 93.75 % at n = 5);
//   - t_mean_interval: mean ± t_{n−1}·s/√n, exact for normal data at every n;
//   - paired_ratio_interval: the median of the per-pair ratios a_i / b_i with median_interval
//     (resamples pairs by construction: each pair is one observation);
//   - ratio_of_medians_interval: two independent samples, each median's interval at 1 − (1 − c)/2
//     (Bonferroni): the ratio lies between the intervals' quotients with confidence ≥ the sum rule.
//
//   const Interval r = paired_ratio_interval(seconds_slow, seconds_fast);   // "2.1× [1.7×, 2.6×] (96 %, n =
//   20)"
#include <cstddef>
#include <vector>

#include "sextant/eval/verdict.hpp"

namespace sextant {

/// Below this many observations the bootstrap intervals of verdict.hpp use the methods here.
constexpr std::size_t kSmallSample = 20;

/// 1 − 2·P(X ≤ j) for X ~ Binomial(n, ½) (X: the values below the median): the coverage of the
/// order-statistic interval [x_(j+1), x_(n−j)] (1-based) of the median; 0 when it is empty.
double order_statistic_coverage(std::size_t n, std::size_t j);

/// Median of the finite values with the order-statistic interval: the narrowest symmetric pair whose
/// coverage reaches `confidence`, else [min, max]; `confidence` of the result is the exact coverage.
Interval median_interval(const std::vector<double>& values, double confidence = 0.95);

/// Mean of the finite values ± the two-sided Student-t quantile with n − 1 degrees of freedom times
/// the standard error. Undefined below two values.
Interval t_mean_interval(const std::vector<double>& values, double confidence = 0.95);

/// Median of a_i / b_i over the pairs where both are finite and b_i > 0, with median_interval.
Interval paired_ratio_interval(const std::vector<double>& a, const std::vector<double>& b,
                               double confidence = 0.95);

/// median(a) / median(b) for independent positive samples: [lo_a / hi_b, hi_a / lo_b] from each
/// median's interval at 1 − (1 − confidence)/2; confidence = 1 − the two intervals' miss rates.
/// Undefined when b's interval reaches 0 or below.
Interval ratio_of_medians_interval(const std::vector<double>& a, const std::vector<double>& b,
                                   double confidence = 0.95);

}  // namespace sextant
