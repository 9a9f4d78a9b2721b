// 2D range–bearing SLAM (§5.2.1.3 A): consistency (NEES) of every filter over Monte-Carlo runs,
// and the UKF's loss of positive definiteness when P0 is scaled up, reported as a status.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>

#include "sextant/core/chi_square.hpp"
#include "sextant/core/pose.hpp"

#include "sextant/filters/covariance.hpp"
#include "sextant/filters/filter.hpp"
#include "sextant/filters/range_bearing_sim.hpp"
#include "sextant/filters/yaml.hpp"

namespace sextant {
namespace {

RangeBearingSimSettings short_run() {
  RangeBearingSimSettings s;
  s.max_steps = 600;  // 30 s, 12 observation epochs
  return s;
}

// Average pose NEES over all steps of all runs (steps after the first observation).
double average_nees(const std::string& name, const YAML::Node& settings, int runs, std::size_t* failures) {
  const RangeBearingSimSettings s = short_run();
  auto model = std::make_shared<RangeBearingModel>(s.model());
  Rng world_rng(1);
  const RangeBearingWorld world = make_range_bearing_world(10, 25.0, world_rng);
  double sum = 0.0;
  std::size_t count = 0;
  for (int run = 0; run < runs; ++run) {
    Rng rng(100 + static_cast<std::uint64_t>(run));
    const RangeBearingRun sim = simulate_range_bearing(world, s, rng);
    auto filter = make_filter(name, model, settings);
    filter->initialize(Eigen::VectorXd::Zero(3), Eigen::MatrixXd::Identity(3, 3) * 1e-6);
    const SlamRunResult result = run_slam(*filter, sim.steps, s.control_noise(), s.observation_noise());
    *failures += result.failed_steps;
    for (std::size_t k = 0; k < result.steps.size(); ++k) {
      if (k < 50) continue;
      Eigen::Vector3d e = result.steps[k].pose - sim.true_poses[k];
      e[2] = wrap_angle(e[2]);
      sum += e.dot(result.steps[k].pose_covariance.ldlt().solve(e));
      ++count;
    }
  }
  return sum / static_cast<double>(count);
}

TEST(RangeBearing, AverageNeesWithinChiSquareBounds) {
  // M runs, 3 pose dof: the M-run average NEES lies in [χ²₀.₀₂₅(3M), χ²₀.₉₇₅(3M)]/M with 95%
  // probability; for M = 6, χ²(18) gives [8.231, 31.526]/6 = [1.372, 5.254].
  const int runs = 6;
  const double lower = chi_square_quantile(0.025, 3 * runs) / runs;
  const double upper = chi_square_quantile(0.975, 3 * runs) / runs;
  for (const std::string name : {"ekf", "ukf", "ckf", "rspkf", "seif"}) {
    std::size_t failures = 0;
    const YAML::Node settings = name == "rspkf" ? YAML::Load("{iterations: 3}") : YAML::Node();
    const double nees = average_nees(name, settings, runs, &failures);
    std::printf("[range-bearing] %-5s average pose NEES %.3f (95%% bounds [%.3f, %.3f]), failed steps %zu\n",
                name.c_str(), nees, lower, upper, failures);
    EXPECT_GT(nees, lower) << name;
    EXPECT_LT(nees, upper) << name;
    EXPECT_EQ(failures, 0u) << name;
  }
}

TEST(RangeBearing, UkfLosesPositiveDefinitenessWhenP0IsScaledUp) {
  // Thesis §5.2.2: increasing the initial covariance makes the UKF lose positive definiteness.
  // With Julier's κ = 3 − n the centre weight is negative, which is what breaks it.
  const RangeBearingSimSettings s = short_run();
  auto model = std::make_shared<RangeBearingModel>(s.model());
  Rng world_rng(1);
  const RangeBearingWorld world = make_range_bearing_world(10, 25.0, world_rng);
  Rng rng(5);
  const RangeBearingRun sim = simulate_range_bearing(world, s, rng);
  auto count_failures = [&](double p0_scale) {
    auto filter = make_filter("ukf", model, YAML::Load("{alpha: 1.0, beta: 0.0, kappa_three_minus_n: true}"));
    filter->initialize(Eigen::VectorXd::Zero(3), Eigen::Vector3d(1.0, 1.0, 0.01).asDiagonal() * p0_scale);
    const SlamRunResult result = run_slam(*filter, sim.steps, s.control_noise(), s.observation_noise());
    return result.summary.failures();
  };
  const std::size_t small = count_failures(1e-4), large = count_failures(100.0);
  std::printf("[ukf-p0] failed steps: P0 x 1e-4 -> %zu, P0 x 100 -> %zu\n", small, large);
  EXPECT_EQ(small, 0u);
  EXPECT_GT(large, 0u);
}

}  // namespace
}  // namespace sextant

namespace sextant {
namespace {

// Issue 23: sigma_range 1e300 ran "ok" with nothing mapped. Noises get physical bounds.
TEST(RangeBearing, NoisesAsLargeAsWhatTheyMeasureAreRefused) {
  RangeBearingSimSettings s;
  std::string why;
  EXPECT_TRUE(s.valid(&why)) << why;
  s.sigma_range = 1e300;
  EXPECT_FALSE(s.valid(&why));
  EXPECT_NE(why.find("sigma_range must be < max_range"), std::string::npos) << why;
  s = RangeBearingSimSettings{};
  s.sigma_bearing = 4.0;
  EXPECT_FALSE(s.valid(&why));
  s = RangeBearingSimSettings{};
  s.sigma_speed = 1e9;
  EXPECT_FALSE(s.valid(&why));
}

}  // namespace
}  // namespace sextant
