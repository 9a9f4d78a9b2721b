// The time lag between an estimated and a true path (E8): known answers.
#include <cmath>

#include <gtest/gtest.h>

#include "sextant/eval/time_lag.hpp"

namespace sextant {
namespace {

/// A circle of radius 5 m at 2 m/s, sampled every `dt` seconds for `seconds`.
TimedPath circle(double dt, double seconds, double delay = 0.0) {
  TimedPath p;
  for (double t = 0; t <= seconds + 1e-9; t += dt) {
    p.t.push_back(t);
    p.x.push_back(5 * std::cos(0.4 * (t - delay)));
    p.y.push_back(5 * std::sin(0.4 * (t - delay)));
  }
  return p;
}

TEST(TimeLag, RecoversADelayBetweenGridPoints) {
  const TimedPath truth = circle(0.1, 40.0);
  const TimedPath late = circle(1.0, 40.0, 0.37);  // the estimate is where the truth was 0.37 s earlier
  const TimeLag lag = estimate_time_lag(truth, late.t, late.x, late.y, 2.0, 0.02);
  EXPECT_NEAR(lag.lag, 0.37, 0.005);
  EXPECT_LT(lag.rms_at_lag, 0.03);                 // the nearest grid point is 0.01 s = 2 cm away
  EXPECT_NEAR(lag.rms_at_zero, 2.0 * 0.37, 0.01);  // 0.74 m behind along the circle
  EXPECT_EQ(lag.taus.size(), 201u);
  const TimedPath early = circle(1.0, 40.0, -0.5);
  EXPECT_NEAR(estimate_time_lag(truth, early.t, early.x, early.y, 2.0, 0.02).lag, -0.5, 0.005);
}

TEST(TimeLag, IdenticalPathsHaveNoLagAndBadGridsThrow) {
  const TimedPath truth = circle(0.1, 20.0);
  const TimeLag lag = estimate_time_lag(truth, truth.t, truth.x, truth.y, 1.0, 0.05);
  EXPECT_NEAR(lag.lag, 0.0, 1e-9);
  EXPECT_NEAR(lag.rms_at_zero, 0.0, 1e-12);
  double x = 0, y = 0;
  EXPECT_FALSE(truth.at(-0.1, &x, &y));
  EXPECT_TRUE(truth.at(0.05, &x, &y));
  EXPECT_THROW(estimate_time_lag(truth, truth.t, truth.x, truth.y, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(estimate_time_lag(truth, truth.t, truth.x, truth.y, 0.1, 0.2), std::invalid_argument);
}

}  // namespace
}  // namespace sextant
