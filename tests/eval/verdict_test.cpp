#include "sextant/eval/verdict.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace sextant {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(Verdict, WilsonIntervalMatchesTheTextbookValue) {
  const Interval w = wilson_interval(8, 10);  // Newcombe (1998), 8/10: 0.4902 to 0.9433
  EXPECT_DOUBLE_EQ(w.estimate, 0.8);
  EXPECT_NEAR(w.lo, 0.4902, 5e-5);
  EXPECT_NEAR(w.hi, 0.9433, 5e-5);
  EXPECT_EQ(w.n, 10u);
  EXPECT_FALSE(wilson_interval(0, 0).defined());
  const Interval all = wilson_interval(10, 10);
  EXPECT_DOUBLE_EQ(all.hi, 1.0);
  EXPECT_LT(all.lo, 1.0);
}

TEST(Verdict, MeanIntervalIsMeanPlusMinusStudentTTimesStandardError) {
  const Interval m = mean_interval({1, 2, 3, 4, 5, kNaN});
  EXPECT_DOUBLE_EQ(m.estimate, 3.0);
  EXPECT_EQ(m.n, 5u);
  EXPECT_NEAR(m.hi - m.estimate, 2.776445 * std::sqrt(2.5 / 5.0), 1e-5);  // t₄, not z = 1.96
  EXPECT_FALSE(mean_interval({1.0}).defined());
}

TEST(Verdict, ExactMcNemarIsTheTwoSidedBinomialTail) {
  EXPECT_NEAR(mcnemar_p_value(10, 2), 2.0 * (1 + 12 + 66) / 4096.0, 1e-12);
  EXPECT_NEAR(mcnemar_p_value(2, 10), mcnemar_p_value(10, 2), 1e-15);
  EXPECT_DOUBLE_EQ(mcnemar_p_value(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(mcnemar_p_value(3, 3), 1.0);
}

TEST(Verdict, PairedDifferenceApproachesTheWaldIntervalForLargeSamples) {
  // 10,000 pairs: 7000 both, 1500 only a, 500 only b, 1000 neither.
  std::vector<bool> a, b;
  const auto add = [&](int count, bool x, bool y) {
    for (int i = 0; i < count; ++i) {
      a.push_back(x);
      b.push_back(y);
    }
  };
  add(7000, true, true);
  add(1500, true, false);
  add(500, false, true);
  add(1000, false, false);
  const PairedRates r = compare_paired_successes(a, b);
  EXPECT_EQ(r.n, 10000u);
  EXPECT_EQ(r.only_a, 1500u);
  EXPECT_EQ(r.only_b, 500u);
  EXPECT_NEAR(r.difference.estimate, 0.1, 1e-12);
  const double n = 10000, wald = 1.959964 * std::sqrt((1500 + 500) - 1000.0 * 1000.0 / n) / n;
  EXPECT_NEAR(r.difference.lo, 0.1 - wald, 1e-3);
  EXPECT_NEAR(r.difference.hi, 0.1 + wald, 1e-3);
  EXPECT_LT(r.p_value, 1e-10);
  EXPECT_EQ(verdict_greater(r.difference, 0.0), Verdict::holds);
}

TEST(Verdict, IdenticalOutcomesGiveAZeroDifferenceThatIsNotSignificant) {
  const std::vector<bool> x{true, true, false, true, false, true, true, true};
  const PairedRates r = compare_paired_successes(x, x);
  EXPECT_DOUBLE_EQ(r.difference.estimate, 0.0);
  EXPECT_LT(r.difference.lo, 0.0);
  EXPECT_GT(r.difference.hi, 0.0);
  EXPECT_DOUBLE_EQ(r.p_value, 1.0);
  EXPECT_EQ(verdict_greater(r.difference, 0.0), Verdict::inconclusive);
}

TEST(Verdict, BootstrapIsDeterministicAndExactOnConstantSamples) {
  const std::vector<double> v{5, 1, 4, 2, 3, 9, 7, 6, 8};
  const Interval a = bootstrap_median(v, 42), b = bootstrap_median(v, 42);
  EXPECT_DOUBLE_EQ(a.lo, b.lo);
  EXPECT_DOUBLE_EQ(a.hi, b.hi);
  EXPECT_DOUBLE_EQ(a.estimate, 5.0);
  EXPECT_LE(a.lo, 5.0);
  EXPECT_GE(a.hi, 5.0);
  const Interval ratio = bootstrap_ratio_of_medians({4, 4, 4}, {2, 2, kNaN}, 1);
  EXPECT_DOUBLE_EQ(ratio.estimate, 2.0);
  EXPECT_DOUBLE_EQ(ratio.lo, 2.0);
  EXPECT_DOUBLE_EQ(ratio.hi, 2.0);
  EXPECT_EQ(verdict_in_band(ratio, 1.5, 3.0), Verdict::holds);
  EXPECT_FALSE(bootstrap_median({kNaN}, 1).defined());
  const Interval d = bootstrap_paired_mean_difference({3, 4, 5}, {1, 2, 3}, 7);
  EXPECT_DOUBLE_EQ(d.estimate, 2.0);
  EXPECT_DOUBLE_EQ(d.lo, 2.0);
}

TEST(Verdict, JarqueBeraOfAKnownSample) {
  // {-1, 0, 1}: skewness 0, m4 / m2² = 1.5, JB = 3/6 · (1.5²/4) = 0.28125.
  const NormalityTest t = jarque_bera({-1, 0, 1});
  EXPECT_NEAR(t.skewness, 0.0, 1e-12);
  EXPECT_NEAR(t.excess_kurtosis, -1.5, 1e-12);
  EXPECT_NEAR(t.statistic, 0.28125, 1e-12);
  EXPECT_NEAR(t.p_value, std::exp(-0.140625), 1e-12);
  // A heavily skewed sample is rejected.
  std::vector<double> skewed(200, 0.0);
  for (int i = 0; i < 10; ++i) skewed[static_cast<std::size_t>(i)] = 50.0;
  EXPECT_LT(jarque_bera(skewed).p_value, 1e-6);
}

TEST(Verdict, IntervalVerdicts) {
  const Interval above{1.0, 0.5, 1.5};
  const Interval straddle{0.2, -0.1, 0.5};
  const Interval below{-1.0, -1.5, -0.5};
  const Interval none{kNaN, kNaN, kNaN};
  EXPECT_EQ(verdict_greater(above, 0.0), Verdict::holds);
  EXPECT_EQ(verdict_greater(straddle, 0.0), Verdict::inconclusive);
  EXPECT_EQ(verdict_greater(below, 0.0), Verdict::does_not_hold);
  EXPECT_EQ(verdict_greater(none, 0.0), Verdict::not_comparable);
  EXPECT_EQ(verdict_less(below, 0.0), Verdict::holds);
  EXPECT_EQ(verdict_less(above, 0.0), Verdict::does_not_hold);
  EXPECT_EQ(verdict_in_band({4.0, 3.0, 5.0}, 2.0, 8.0), Verdict::holds);
  EXPECT_EQ(verdict_in_band({9.0, 7.0, 11.0}, 2.0, 8.0), Verdict::inconclusive);
  EXPECT_EQ(verdict_in_band({12.0, 10.0, 14.0}, 2.0, 8.0), Verdict::does_not_hold);
  EXPECT_EQ(verdict_all({Verdict::holds, Verdict::inconclusive}), Verdict::inconclusive);
  EXPECT_EQ(verdict_all({Verdict::holds, Verdict::does_not_hold, Verdict::inconclusive}),
            Verdict::does_not_hold);
  EXPECT_EQ(verdict_all({Verdict::holds, Verdict::holds}), Verdict::holds);
  EXPECT_EQ(verdict_all({}), Verdict::not_comparable);
  EXPECT_EQ(describe(Interval{0.5, 0.25, 0.75, 0.95, 12}, "×"), "0.50× [0.25×, 0.75×] (95 %, n = 12)");
}

}  // namespace
}  // namespace sextant
