// χ² CDF and quantiles, and the normal quantile, against printed table values (Abramowitz & Stegun,
// tables 26.1 and 26.8).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "sextant/core/chi_square.hpp"

namespace sextant {
namespace {

TEST(ChiSquare, QuantilesMatchTables) {
  struct Row {
    double p, dof, x;
  };
  for (const Row& r : {Row{0.95, 1, 3.841459}, Row{0.95, 2, 5.991465}, Row{0.95, 4, 9.487729},
                       Row{0.999, 3, 16.26624}, Row{0.999, 4, 18.46683}, Row{0.025, 20, 9.590777},
                       Row{0.975, 20, 34.16961}, Row{0.5, 10, 9.341818}, Row{0.01, 100, 70.06489}}) {
    EXPECT_NEAR(chi_square_quantile(r.p, r.dof), r.x, 1e-5 * r.x) << r.p << " " << r.dof;
    EXPECT_NEAR(chi_square_cdf(r.x, r.dof), r.p, 1e-6) << r.p << " " << r.dof;
  }
}

TEST(ChiSquare, QuantilesToNineDigits) {
  EXPECT_NEAR(chi_square_quantile(0.95, 3), 7.814727903, 1e-9);
  EXPECT_NEAR(chi_square_quantile(0.99, 4), 13.27670414, 1e-8);
  EXPECT_NEAR(chi_square_cdf(7.814727903, 3), 0.95, 1e-10);
}

TEST(NormalQuantile, MatchesTables) {
  EXPECT_NEAR(normal_quantile(0.975), 1.959963985, 1e-9);
  EXPECT_NEAR(normal_quantile(0.995), 2.575829304, 1e-9);
  EXPECT_NEAR(normal_quantile(0.5), 0.0, 1e-15);
  EXPECT_NEAR(normal_quantile(0.025), -1.959963985, 1e-9);
  EXPECT_THROW(normal_quantile(0.0), std::invalid_argument);
  EXPECT_THROW(normal_quantile(1.0), std::invalid_argument);
}

TEST(ChiSquare, ClosedFormsForTwoDegreesOfFreedom) {
  for (double x : {0.01, 0.5, 2.0, 7.0, 30.0}) EXPECT_NEAR(chi_square_cdf(x, 2), 1 - std::exp(-x / 2), 1e-14);
  EXPECT_EQ(chi_square_cdf(0.0, 3), 0.0);
  EXPECT_EQ(chi_square_cdf(-1.0, 3), 0.0);
}

TEST(ChiSquare, RejectsInvalidArguments) {
  EXPECT_THROW(chi_square_quantile(0.0, 3), std::invalid_argument);
  EXPECT_THROW(chi_square_quantile(1.0, 3), std::invalid_argument);
  EXPECT_THROW(chi_square_quantile(0.5, 0), std::invalid_argument);
  EXPECT_THROW(chi_square_cdf(1.0, -1), std::invalid_argument);
}

}  // namespace
}  // namespace sextant
