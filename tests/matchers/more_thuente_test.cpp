// The Moré–Thuente line search on the six test functions of Moré & Thuente (1994), §5, and the
// `more_thuente` step control of NDT on a synthetic pair with a known transform.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "optim/more_thuente.hpp"
#include "pose_errors.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/units.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/ndt_matcher.hpp"
#include "sextant/matchers/samplers.hpp"
#include "sextant/matchers/yaml.hpp"
#include "test_clouds.hpp"

namespace sextant {
namespace {

constexpr double kPi = 3.14159265358979323846;

using Phi = std::function<LineSearchSample(double)>;

/// Function 1 of §5: φ(α) = −α / (α² + β).
Phi rational(double beta) {
  return [beta](double a) {
    const double d = a * a + beta;
    return LineSearchSample{-a / d, (a * a - beta) / (d * d), true};
  };
}

/// Function 2: φ(α) = (α + β)⁵ − 2(α + β)⁴.
Phi quintic(double beta) {
  return [beta](double a) {
    const double x = a + beta;
    return LineSearchSample{std::pow(x, 5) - 2.0 * std::pow(x, 4),
                            5.0 * std::pow(x, 4) - 8.0 * std::pow(x, 3), true};
  };
}

/// Function 3: φ(α) = φ₀(α) + 2(1 − β)/(lπ)·sin(lπα/2), φ₀ = 1 − α (α ≤ 1 − β), α − 1 (α ≥ 1 + β),
/// (α − 1)²/(2β) + β/2 between.
Phi wiggly(double beta, double l) {
  return [beta, l](double a) {
    double f = 0.0, g = 0.0;
    if (a <= 1.0 - beta) {
      f = 1.0 - a;
      g = -1.0;
    } else if (a >= 1.0 + beta) {
      f = a - 1.0;
      g = 1.0;
    } else {
      f = (a - 1.0) * (a - 1.0) / (2.0 * beta) + beta / 2.0;
      g = (a - 1.0) / beta;
    }
    const double c = 2.0 * (1.0 - beta) / (l * kPi), w = l * kPi / 2.0;
    return LineSearchSample{f + c * std::sin(w * a), g + c * w * std::cos(w * a), true};
  };
}

/// Functions 4–6: φ(α) = γ(β₁)·√((1 − α)² + β₂²) + γ(β₂)·√(α² + β₁²), γ(β) = √(1 + β²) − β.
Phi yanai(double b1, double b2) {
  const auto gamma = [](double b) { return std::sqrt(1.0 + b * b) - b; };
  const double g1 = gamma(b1), g2 = gamma(b2);
  return [b1, b2, g1, g2](double a) {
    const double s1 = std::sqrt((1.0 - a) * (1.0 - a) + b2 * b2), s2 = std::sqrt(a * a + b1 * b1);
    return LineSearchSample{g1 * s1 + g2 * s2, g1 * (a - 1.0) / s1 + g2 * a / s2, true};
  };
}

struct PaperCase {
  const char* name;
  Phi phi;
  double mu, eta;
  std::vector<int> evaluations;  ///< the paper's tables 1–6, for α₀ = 10⁻³, 10⁻¹, 10, 10³
  std::vector<double> steps;     ///< α the paper reports (to its printed digits)
};

TEST(MoreThuente, PaperTestFunctionsMeetStrongWolfeWithinThePapersEvaluations) {
  const std::vector<PaperCase> cases = {
      {"1: -a/(a^2+2)", rational(2.0), 1e-3, 0.1, {6, 3, 1, 4}, {1.4, 1.4, 10, 37}},
      {"2: (a+b)^5-2(a+b)^4", quintic(0.004), 0.1, 0.1, {12, 8, 8, 11}, {1.6, 1.6, 1.6, 1.6}},
      {"3: wiggly, b=0.01 l=39", wiggly(0.01, 39), 0.1, 0.1, {12, 12, 10, 13}, {1.0, 1.0, 1.0, 1.0}},
      {"4: b1=b2=0.001", yanai(0.001, 0.001), 1e-3, 1e-3, {4, 1, 3, 4}, {0.08, 0.10, 0.35, 0.83}},
      {"5: b1=0.01 b2=0.001", yanai(0.01, 0.001), 1e-3, 1e-3, {6, 3, 7, 8}, {0.075, 0.078, 0.073, 0.076}},
      {"6: b1=0.001 b2=0.01", yanai(0.001, 0.01), 1e-3, 1e-3, {13, 11, 8, 11}, {0.93, 0.93, 0.92, 0.92}},
  };
  const double initial[] = {1e-3, 1e-1, 1e1, 1e3};
  for (const PaperCase& c : cases) {
    MoreThuenteSettings s;
    s.mu = c.mu;
    s.eta = c.eta;
    s.iterations = 100;
    ASSERT_TRUE(s.valid(nullptr));
    const LineSearchSample origin = c.phi(0.0);
    ASSERT_LT(origin.slope, 0.0) << c.name;
    for (std::size_t i = 0; i < 4; ++i) {
      int calls = 0;
      const Phi counted = [&](double a) {
        ++calls;
        return c.phi(a);
      };
      const LineSearchResult r = more_thuente(counted, origin, initial[i], 0.0, 1e10, s);
      const std::string what = std::string(c.name) + ", alpha0 = " + std::to_string(initial[i]);
      EXPECT_EQ(r.end, LineSearchEnd::kStrongWolfe) << what;
      EXPECT_TRUE(strong_wolfe(origin, r.step, c.phi(r.step), c.mu, c.eta)) << what << ": alpha " << r.step;
      EXPECT_EQ(r.evaluations, calls) << what;
      EXPECT_LE(r.evaluations, c.evaluations[i]) << what;
      EXPECT_NEAR(r.step, c.steps[i], std::max(0.05 * c.steps[i], 0.006)) << what;
    }
  }
}

TEST(MoreThuente, StrongWolfeRejectsStepsThatBreakEitherCondition) {
  const Phi phi = rational(2.0);
  const LineSearchSample origin = phi(0.0);
  EXPECT_TRUE(strong_wolfe(origin, std::sqrt(2.0), phi(std::sqrt(2.0)), 1e-3, 0.1));  // the minimiser
  EXPECT_FALSE(strong_wolfe(origin, 0.01, phi(0.01), 1e-3, 0.1));  // still steep: eq. (1.2) fails
  EXPECT_FALSE(strong_wolfe(origin, 1e4, phi(1e4), 0.5, 0.9));     // too little decrease: eq. (1.1)
}

TEST(MoreThuente, ShortensStepsWithoutAValueAndStopsAtTheBounds) {
  // φ = (α − 1)², undefined beyond α = 0.5: the search may only return a step it could evaluate.
  const Phi holed = [](double a) { return LineSearchSample{(a - 1) * (a - 1), 2 * (a - 1), a <= 0.5}; };
  MoreThuenteSettings s;
  LineSearchResult r = more_thuente(holed, holed(0.0), 1.0, 0.0, 10.0, s);
  EXPECT_GT(r.step, 0.0);
  EXPECT_LE(r.step, 0.5);
  EXPECT_LT(r.at.value, 1.0);
  // The minimiser α = 1 lies beyond α_max = 0.3, where |φ'| = 1.4 > η·|φ'(0)| = 0.2: the search
  // ends at α_max.
  const Phi bowl = [](double a) { return LineSearchSample{(a - 1) * (a - 1), 2 * (a - 1), true}; };
  s.eta = 0.1;
  r = more_thuente(bowl, bowl(0.0), 1.0, 0.0, 0.3, s);
  EXPECT_EQ(r.end, LineSearchEnd::kAtMaxStep);
  EXPECT_DOUBLE_EQ(r.step, 0.3);
  // Uphill: no step.
  const Phi up = [](double a) { return LineSearchSample{a, 1.0, true}; };
  r = more_thuente(up, up(0.0), 1.0, 0.0, 10.0, s);
  EXPECT_EQ(r.end, LineSearchEnd::kNotDescent);
  EXPECT_EQ(r.step, 0.0);
  EXPECT_EQ(r.evaluations, 0);
}

TEST(MoreThuente, SettingsBounds) {
  MoreThuenteSettings s;
  EXPECT_TRUE(s.valid(nullptr));
  std::string why;
  s.mu = 0.0;
  EXPECT_FALSE(s.valid(&why));
  EXPECT_NE(why.find("line_search_mu"), std::string::npos);
  s = MoreThuenteSettings{};
  s.eta = 1e-5;  // below μ = 1e-4
  EXPECT_FALSE(s.valid(&why));
  s = MoreThuenteSettings{};
  s.max_step = 0.0;
  EXPECT_FALSE(s.valid(&why));
  s = MoreThuenteSettings{};
  s.iterations = 0;
  EXPECT_FALSE(s.valid(&why));
  EXPECT_THROW(make_matcher("ndt", YAML::Load("{step_control: more_thuente, line_search_eta: 1.5}")),
               InputError);
  EXPECT_THROW(make_matcher("ndt", YAML::Load("{step_control: more_thuente, line_search_iterations: 0}")),
               InputError);
  const NdtSettings read = read_ndt_settings(
      YAML::Load("{step_control: more_thuente, line_search_mu: 0.001, line_search_eta: 0.1, "
                 "line_search_max_step: 0.5, line_search_iterations: 20}"),
      "test");
  EXPECT_EQ(read.optimizer.step_control, StepControl::kMoreThuente);
  EXPECT_DOUBLE_EQ(read.optimizer.line_search.mu, 0.001);
  EXPECT_DOUBLE_EQ(read.optimizer.line_search.eta, 0.1);
  EXPECT_DOUBLE_EQ(read.optimizer.line_search.max_step, 0.5);
  EXPECT_EQ(read.optimizer.line_search.iterations, 20);
}

TEST(MoreThuente, NdtRecoversKnownTransformWithMonotoneScore) {
  // The yard seen from two poses (input = T⁻¹·scene, freshly sampled): p_ref = T·p_input.
  const Eigen::Isometry3d T = test::pose(0.9, -0.6, 0.05, 0.5, -0.5, 6.0);
  Rng rng(7), rng2(107), rng3(207);
  const PointCloud reference = test::yard(rng), scene = test::yard(rng2);
  const PointCloud input =
      scene.subset(GridSampler(GridSamplerSettings{1.0, 5, 3}).select(scene, rng3)).transformed(T.inverse());
  auto matcher = make_matcher("ndt", YAML::Load("{step_control: more_thuente, cell_size: 2.0}"));
  matcher->set_reference(reference);
  const RegistrationResult r = matcher->align(input, Eigen::Isometry3d::Identity());
  EXPECT_TRUE(r.converged) << r.summary();
  EXPECT_LT(test::translation_error(T, r.T), 0.05) << r.summary();
  EXPECT_LT(test::rotation_error(T, r.T) / kRadPerDeg, 0.3);
  ASSERT_GE(r.trace.size(), 2u);
  // Every accepted step meets eq. (1.1): the score never rises from one iteration to the next.
  for (std::size_t i = 1; i < r.trace.size(); ++i)
    EXPECT_LE(r.trace[i].score, r.trace[i - 1].score) << "iteration " << r.trace[i].iteration;
  // No step is longer than line_search_max_step (1 by default).
  for (const IterationTrace& row : r.trace) EXPECT_LE(row.step_norm, 1.0 + 1e-9);
}

}  // namespace
}  // namespace sextant
