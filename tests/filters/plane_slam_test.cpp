// Plane SLAM on a small synthetic plane world: the filters must end far closer to the truth
// than dead reckoning with the same (biased, noisy) odometry.
#include <gtest/gtest.h>

#include "plane_world.hpp"
#include "sextant/filters/filter.hpp"
#include "sextant/filters/yaml.hpp"

namespace sextant {
namespace {

TEST(PlaneSlam, FiltersBeatOdometry) {
  const test::PlaneWorld world = test::make_plane_world(60, 5);
  auto model = std::make_shared<PlaneSlamModel>();
  const double odometry_error = test::position_error(world.odometry.back().vector(), world.truth.back());
  for (const std::string name : {"ekf", "ukf", "ckf", "rspkf", "seif"}) {
    auto filter = make_filter(name, model, name == "rspkf" ? YAML::Load("{iterations: 4}") : YAML::Node());
    const auto known = test::start_plane_slam(*filter, world);
    const SlamRunResult run = run_slam(*filter, world.steps, world.Q, world.R, {}, known);
    double worst = 0.0;
    for (std::size_t k = 0; k < run.steps.size(); ++k)
      worst = std::max(worst, test::position_error(run.steps[k].pose, world.truth[k + 1]));
    const double final_error = test::position_error(run.steps.back().pose, world.truth.back());
    std::printf(
        "[plane-slam] %-5s final position error %.3f m (worst %.3f m), odometry %.3f m, failed steps %zu\n",
        name.c_str(), final_error, worst, odometry_error, run.failed_steps);
    EXPECT_EQ(run.failed_steps, 0u) << name;
    EXPECT_LT(final_error, 0.2 * odometry_error) << name;
    EXPECT_EQ(filter->num_landmarks(), static_cast<int>(world.planes.size())) << name;
  }
}

TEST(PlaneSlam, EifEqualsEkfOnTheNonlinearProblem) {
  const test::PlaneWorld world = test::make_plane_world(20, 9);
  auto model = std::make_shared<PlaneSlamModel>();
  auto ekf = make_filter("ekf", model);
  auto eif = make_filter("eif", model);
  const auto known_ekf = test::start_plane_slam(*ekf, world);
  const auto known_eif = test::start_plane_slam(*eif, world);
  const SlamRunResult a = run_slam(*ekf, world.steps, world.Q, world.R, {}, known_ekf);
  const SlamRunResult b = run_slam(*eif, world.steps, world.Q, world.R, {}, known_eif);
  EXPECT_LT((ekf->mean() - eif->mean()).norm(), 1e-7);
  EXPECT_LT((ekf->covariance() - eif->covariance()).norm() / ekf->covariance().norm(), 1e-7);
}

}  // namespace
}  // namespace sextant
