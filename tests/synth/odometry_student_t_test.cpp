// The student_t odometry model (issue 27): tail fractions of many draws match Student's t with
// ν = 3 (closed-form CDF), a very large ν gives the Gaussian's, and ν ≤ 1 is refused.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/core/units.hpp"
#include "sextant/synth/odometry.hpp"
#include "sextant/synth/settings.hpp"
#include "sextant/synth/yaml.hpp"

namespace sextant::synth {
namespace student_t_test {

/// The share of |x| / scale above `bound`.
double tail_share(const std::vector<double>& x, double scale, double bound) {
  double n = 0;
  for (const double v : x) n += std::abs(v) / scale > bound ? 1.0 : 0.0;
  return n / static_cast<double>(x.size());
}

struct Draws {
  std::vector<double> forward, lateral, heading;
};

Draws draw(const OdometrySettings& s, std::uint64_t seed, int n) {
  Rng rng(seed);
  Draws d;
  for (int i = 0; i < n; ++i) {
    const Increment2D e = corrupt_increment(Increment2D{}, s, rng);
    d.forward.push_back(e.forward);
    d.lateral.push_back(e.lateral);
    d.heading.push_back(e.heading);
  }
  return d;
}

/// A share p of n independent draws has the binomial standard error √(p(1 − p)/n); the tests allow
/// 5 of them (a false failure about once in 1.7 million runs; the seeds are fixed anyway).
double tolerance(double p, int n) {
  return 5.0 * std::sqrt(p * (1.0 - p) / n);
}

TEST(StudentTOdometry, TailSharesMatchStudentsTWithThreeDegreesOfFreedom) {
  OdometrySettings s;
  s.model = "student_t";  // ν = 3, scales 20 cm and 1°
  const int n = 200000;
  const Draws d = draw(s, 27, n);
  // Two-sided quantiles of t₃ from F(t) = ½ + (1/π)(u/(1 + u²) + atan u), u = t/√3:
  // P(|t| > 0.764892) = 0.5, P(|t| > 3.182446) = 0.05, P(|t| > 5.840909) = 0.01.
  for (const auto* x : {&d.forward, &d.lateral}) {
    EXPECT_NEAR(tail_share(*x, 0.2, 0.764892), 0.5, tolerance(0.5, n));
    EXPECT_NEAR(tail_share(*x, 0.2, 3.182446), 0.05, tolerance(0.05, n));
    EXPECT_NEAR(tail_share(*x, 0.2, 5.840909), 0.01, tolerance(0.01, n));
  }
  EXPECT_NEAR(tail_share(d.heading, kRadPerDeg, 3.182446), 0.05, tolerance(0.05, n));
  // The Gaussian's 95 % bound is exceeded far more often: P(|t₃| > 1.959964) = 0.1449.
  EXPECT_NEAR(tail_share(d.forward, 0.2, 1.959964), 0.14486, tolerance(0.14486, n));
  double sum = 0;
  for (const double v : d.forward) sum += v;
  // Zero mean: the standard error of the mean is √(ν/(ν−2)) · 0.2 / √n = 0.00077 m.
  EXPECT_NEAR(sum / n, 0.0, 5 * std::sqrt(3.0) * 0.2 / std::sqrt(n));
}

TEST(StudentTOdometry, LargeDegreesOfFreedomApproachTheGaussianModel) {
  OdometrySettings t;
  t.model = "student_t";
  t.student_t_dof = 1e6;  // t_ν → N(0, 1): the quantile differs from the normal's by O(1/ν)
  OdometrySettings g;
  g.model = "gaussian";  // the same scales, 20 cm and 1°
  const int n = 200000;
  const Draws dt = draw(t, 5, n), dg = draw(g, 6, n);
  for (const Draws* d : {&dt, &dg}) {
    EXPECT_NEAR(tail_share(d->forward, 0.2, 1.959964), 0.05, tolerance(0.05, n));
    EXPECT_NEAR(tail_share(d->lateral, 0.2, 2.575829), 0.01, tolerance(0.01, n));
    EXPECT_NEAR(tail_share(d->heading, kRadPerDeg, 0.674490), 0.5, tolerance(0.5, n));
    // Sample kurtosis 3 for a Gaussian; its standard error is √(24/n) = 0.011.
    double m2 = 0, m4 = 0;
    for (const double v : d->forward) {
      m2 += v * v;
      m4 += v * v * v * v;
    }
    m2 /= n;
    m4 /= n;
    EXPECT_NEAR(m4 / (m2 * m2), 3.0, 5 * std::sqrt(24.0 / n));
    EXPECT_NEAR(std::sqrt(m2), 0.2, 5 * 0.2 / std::sqrt(2.0 * n));  // s.e. of σ̂: σ/√(2n)
  }
}

TEST(StudentTOdometry, DegreesOfFreedomWithoutAMeanAreRefused) {
  OdometrySettings s;
  s.model = "student_t";
  std::string why;
  EXPECT_TRUE(s.valid(&why)) << why;
  for (const double dof : {1.0, 0.5, 0.0, -3.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    s.student_t_dof = dof;
    why.clear();
    EXPECT_FALSE(s.valid(&why)) << dof;
    EXPECT_NE(why.find("student_t_dof"), std::string::npos) << why;
  }
  s.student_t_dof = 3.0;
  s.student_t_translation = -0.1;
  EXPECT_FALSE(s.valid(&why));
  std::string message;
  try {
    read_campus_settings(YAML::Load("odometry:\n  model: student_t\n  student_t_dof: 1\n"), "c.yaml");
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("c.yaml"), std::string::npos) << message;
  EXPECT_NE(message.find("student_t_dof"), std::string::npos) << message;
  EXPECT_NE(message.find("above 1"), std::string::npos) << message;
}

TEST(StudentTOdometry, SeededDrawsRepeat) {
  Rng a(3), b(3);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(student_t_draw(2.5, a), student_t_draw(2.5, b));
}

}  // namespace student_t_test
}  // namespace sextant::synth
