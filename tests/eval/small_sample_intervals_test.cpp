// The small-sample intervals have the coverage they state: exact binomial coverage for the
// order-statistic median interval (checked against its definition and by simulation), the Student-t
// quantile for the mean, and the Bonferroni sum for a ratio of two medians.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "sextant/eval/small_sample_intervals.hpp"
#include "sextant/eval/verdict.hpp"

namespace sextant {
namespace {

TEST(SmallSampleIntervals, OrderStatisticCoverageIsTheBinomialSum) {
  // [min, max] misses the median only when all n fall on one side: 1 − 2·(½)ⁿ.
  EXPECT_DOUBLE_EQ(order_statistic_coverage(5, 0), 1.0 - 2.0 / 32.0);
  // n = 20, [x(5), x(16)]: 1 − 2·P(X ≤ 4), X ~ B(20, ½) = 1 − 2·6196/1048576 = 0.98818.
  EXPECT_NEAR(order_statistic_coverage(20, 4), 1.0 - 2.0 * 6196.0 / 1048576.0, 1e-12);
  EXPECT_NEAR(order_statistic_coverage(5, 2), 0.0, 1e-12);  // [x(3), x(3)]: a point covers nothing
  EXPECT_EQ(order_statistic_coverage(4, 2), 0.0);           // no interval left
}

TEST(SmallSampleIntervals, TheMedianIntervalStatesTheCoverageItHas) {
  const Interval five = median_interval({3, 1, 5, 2, 4});
  EXPECT_DOUBLE_EQ(five.estimate, 3.0);
  EXPECT_DOUBLE_EQ(five.lo, 1.0);  // too few values for 95 %: [min, max] with its 93.75 %
  EXPECT_DOUBLE_EQ(five.hi, 5.0);
  EXPECT_DOUBLE_EQ(five.confidence, 0.9375);
  std::vector<double> twenty;
  for (int i = 1; i <= 20; ++i) twenty.push_back(i);
  const Interval i20 = median_interval(twenty);
  // The narrowest symmetric pair with ≥ 95 %: dropping 5 values on each side covers
  // 1 − 2·P(X ≤ 5) = 0.9586, dropping 6 only 0.8847.
  EXPECT_DOUBLE_EQ(i20.lo, 6.0);
  EXPECT_DOUBLE_EQ(i20.hi, 15.0);
  EXPECT_NEAR(i20.confidence, 1.0 - 2.0 * 21700.0 / 1048576.0, 1e-12);
  EXPECT_GE(i20.confidence, 0.95);
}

TEST(SmallSampleIntervals, CoverageBySimulationMatchesTheStatedOne) {
  std::mt19937_64 gen(7);
  std::lognormal_distribution<double> skewed(0.0, 1.0);  // median 1, mean e^½
  std::normal_distribution<double> normal(2.0, 3.0);
  const int trials = 4000;
  for (const std::size_t n : {3u, 8u, 15u}) {
    int median_hits = 0, mean_hits = 0;
    double stated = 0.0;
    for (int t = 0; t < trials; ++t) {
      std::vector<double> a(n), b(n);
      for (double& v : a) v = skewed(gen);
      for (double& v : b) v = normal(gen);
      const Interval m = median_interval(a);
      stated = m.confidence;
      median_hits += m.lo <= 1.0 && 1.0 <= m.hi;
      const Interval t_mean = t_mean_interval(b);
      mean_hits += t_mean.lo <= 2.0 && 2.0 <= t_mean.hi;
    }
    // Binomial standard error of a 95 % rate over 4000 trials: 0.34 %; allow 4 of them.
    EXPECT_NEAR(median_hits / double(trials), stated, 0.014) << "n = " << n;
    EXPECT_NEAR(mean_hits / double(trials), 0.95, 0.014) << "n = " << n;
  }
}

TEST(SmallSampleIntervals, StudentTIsWiderThanTheNormalApproximationAtSmallN) {
  const Interval t = t_mean_interval({1.0, 2.0, 3.0});  // mean 2, s = 1, se = 1/√3, t₂ = 4.3027
  EXPECT_DOUBLE_EQ(t.estimate, 2.0);
  EXPECT_NEAR(t.hi - t.estimate, 4.302653 / std::sqrt(3.0), 1e-5);
  EXPECT_NEAR(mean_interval({1.0, 2.0, 3.0}).hi, t.hi, 1e-12);  // mean_interval is the t interval
}

TEST(SmallSampleIntervals, PairedRatiosAreOneObservationPerPair) {
  // Every pair 2× slower, whatever the pair's own size: the paired ratio is exactly 2, where the
  // ratio of the two medians' intervals spans the pairs' spread.
  const std::vector<double> fast{0.1, 1.0, 10.0, 0.5, 5.0, 2.0, 0.2, 3.0};
  std::vector<double> slow;
  for (double f : fast) slow.push_back(2.0 * f);
  const Interval paired = paired_ratio_interval(slow, fast);
  EXPECT_DOUBLE_EQ(paired.lo, 2.0);
  EXPECT_DOUBLE_EQ(paired.hi, 2.0);
  const Interval apart = ratio_of_medians_interval(slow, fast);
  EXPECT_LT(apart.lo, 1.0);
  EXPECT_GT(apart.hi, 4.0);
  // Each median's interval at ≥ 97.5 % ([min, max] of 8: 99.2 %), joint 1 − 2·0.78 % = 98.4 %.
  EXPECT_NEAR(apart.confidence, 1.0 - 2.0 * 2.0 / 256.0, 1e-12);
}

TEST(SmallSampleIntervals, BootstrapsSwitchToTheExactIntervalsBelowTwentyValues) {
  const std::vector<double> v{4, 1, 3, 2, 5};
  const Interval b = bootstrap_median(v, 1);
  EXPECT_DOUBLE_EQ(b.confidence, 0.9375);  // the order-statistic interval, not a 95 % bootstrap
  const Interval d = bootstrap_paired_mean_difference({2, 3, 4}, {1, 1, 1}, 1);
  EXPECT_NEAR(d.hi, t_mean_interval({1, 2, 3}).hi, 1e-12);
}

}  // namespace
}  // namespace sextant
