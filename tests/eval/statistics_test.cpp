#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sextant/eval/statistics.hpp"

namespace sextant {
namespace {

TEST(Statistics, KnownSample) {
  const SampleStats s = summarize({4.0, 1.0, 3.0, 2.0});
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(5.0 / 3.0));
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
  EXPECT_DOUBLE_EQ(s.rms, std::sqrt(7.5));
  EXPECT_DOUBLE_EQ(s.median, 2.5);
  EXPECT_DOUBLE_EQ(summarize({3.0, 1.0, 2.0}).median, 2.0);
}

TEST(Statistics, SkipsNonFiniteAndHandlesEmpty) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const SampleStats s = summarize({nan, 2.0, std::numeric_limits<double>::infinity()});
  EXPECT_EQ(s.count, 1u);
  EXPECT_DOUBLE_EQ(s.mean, 2.0);
  EXPECT_DOUBLE_EQ(s.std, 0.0);
  const SampleStats e = summarize({});
  EXPECT_EQ(e.count, 0u);
  EXPECT_DOUBLE_EQ(e.mean, 0.0);
  EXPECT_DOUBLE_EQ(rms({}), 0.0);
}

TEST(Statistics, MeanAndMedianOfTheFiniteValuesAreNanWhenThereAreNone) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(mean_of({nan, 1.0, inf, 2.0, 6.0}), 3.0);
  EXPECT_DOUBLE_EQ(median_of({nan, 7.0, 1.0, -inf, 2.0}), 2.0);
  EXPECT_DOUBLE_EQ(median_of({4.0, nan, 1.0, 3.0, 2.0}), 2.5);
  EXPECT_TRUE(std::isnan(mean_of({nan, inf})));
  EXPECT_TRUE(std::isnan(median_of({})));
}

}  // namespace
}  // namespace sextant
