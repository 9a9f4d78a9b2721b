// Known answers for the sequence analyses of E17 and E19 (sequence_analysis.hpp).
#include "sextant/eval/sequence_analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sextant/core/rng.hpp"

namespace sextant {
namespace {

TEST(SequenceAnalysis, FitLineIsExactOnALineAndSkipsNaN) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const LineFit f = fit_line({0, 1, 2, 3, nan, 5}, {1, 3, 5, 7, 100, 11});
  ASSERT_TRUE(f.defined());
  EXPECT_EQ(f.n, 5u);
  EXPECT_NEAR(f.slope, 2.0, 1e-12);
  EXPECT_NEAR(f.intercept, 1.0, 1e-12);
  EXPECT_FALSE(fit_line({1, 1, 1}, {1, 2, 3}).defined());  // x constant
  EXPECT_FALSE(fit_line({1}, {1}).defined());
}

TEST(SequenceAnalysis, FitLineMatchesHandComputedLeastSquares) {
  // x = 0, 1, 2; y = 0, 2, 1: x̄ = 1, ȳ = 1, Sxy = (−1)(−1) + 0 + (1)(0) = 1, Sxx = 2.
  const LineFit f = fit_line({0, 1, 2}, {0, 2, 1});
  EXPECT_NEAR(f.slope, 0.5, 1e-12);
  EXPECT_NEAR(f.intercept, 0.5, 1e-12);
}

TEST(SequenceAnalysis, BootstrapSlopeIsDegenerateOnALineAndCoversANoisySlope) {
  const Interval exact = bootstrap_slope({0, 1, 2, 3, 4}, {3, 2.5, 2, 1.5, 1}, 7);
  EXPECT_NEAR(exact.estimate, -0.5, 1e-12);
  EXPECT_NEAR(exact.lo, -0.5, 1e-12);
  EXPECT_NEAR(exact.hi, -0.5, 1e-12);
  EXPECT_EQ(exact.n, 5u);

  Rng rng(3);
  std::vector<double> x, flat, rising;
  for (int i = 0; i < 300; ++i) {
    x.push_back(i);
    flat.push_back(5.0 + rng.normal());
    rising.push_back(5.0 + 0.1 * i + rng.normal());
  }
  const Interval f = bootstrap_slope(x, flat, 11), r = bootstrap_slope(x, rising, 11);
  EXPECT_LT(f.lo, 0.0);
  EXPECT_GT(f.hi, 0.0);
  EXPECT_LT(f.hi - f.lo, 0.02);
  EXPECT_LT(r.lo, 0.1);
  EXPECT_GT(r.hi, 0.1);
  EXPECT_GT(r.lo, 0.09);
  EXPECT_EQ(verdict_greater(r, 0.0), Verdict::holds);
  EXPECT_EQ(verdict_greater(f, 0.0), Verdict::inconclusive);
  // Same seed, same interval.
  const Interval again = bootstrap_slope(x, rising, 11);
  EXPECT_EQ(again.lo, r.lo);
  EXPECT_EQ(again.hi, r.hi);
  EXPECT_FALSE(bootstrap_slope({1, 1}, {1, 2}, 1).defined());
}

TEST(SequenceAnalysis, RobustSpikesFindIsolatedPeaksOncePerNeighbourhood) {
  std::vector<double> v(100, 1.0);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] += 0.1 * ((i * 7) % 5);  // 1.0 … 1.4, MAD 0.1
  v[20] = 10.0;
  v[21] = 9.0;  // same neighbourhood as 20: one spike
  v[70] = 5.0;
  v[90] = 1.6;  // z = (1.6 − 1.2) / 0.148 ≈ 2.7: not a spike at threshold 5
  EXPECT_EQ(robust_spikes(v, 5.0, 5), (std::vector<std::size_t>{20, 70}));
  EXPECT_EQ(robust_spikes(v, 2.0, 5), (std::vector<std::size_t>{20, 70, 90}));
  EXPECT_TRUE(robust_spikes({}, 5.0, 5).empty());
  // MAD 0: every value above the median is a spike (then thinned by the neighbourhood).
  EXPECT_EQ(robust_spikes({1, 1, 1, 1, 3, 1, 1, 1, 1}, 5.0, 2), (std::vector<std::size_t>{4}));
}

TEST(SequenceAnalysis, RevisitStartsOnASquareLoopDrivenTwice) {
  // 0..39 around a 10 m square (1 m steps), then around again: the second lap revisits from 40 on.
  std::vector<Eigen::Vector3d> p;
  for (int lap = 0; lap < 2; ++lap)
    for (int i = 0; i < 40; ++i) {
      const int side = i / 10, t = i % 10;
      const double xs[4] = {double(t), 10.0, 10.0 - t, 0.0}, ys[4] = {0.0, double(t), 10.0, 10.0 - t};
      p.emplace_back(xs[side], ys[side], 0.0);
    }
  EXPECT_EQ(revisit_starts(p, 0.5, 20), (std::vector<std::size_t>{40}));
  // With a gap longer than the route nothing revisits.
  EXPECT_TRUE(revisit_starts(p, 0.5, 100).empty());
  EXPECT_EQ(distance_to_nearest({35, 41, 79}, {40}), (std::vector<std::size_t>{5, 1, 39}));
  EXPECT_EQ(distance_to_nearest({3}, {}).front(), std::numeric_limits<std::size_t>::max());
}

}  // namespace
}  // namespace sextant
