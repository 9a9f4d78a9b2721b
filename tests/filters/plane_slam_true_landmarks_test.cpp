// Plane SLAM on the synthetic campus with its true plane landmarks, true data association and
// ground truth (issue 6, "Done when"): EKF, UKF and CKF, driven by the campus' 2D odometry,
// must end with a position error well below the odometry's. Observations are the true planes
// seen from the true pose (eq. 4.64) plus Gaussian noise matching R; no extraction, no
// semantic association (plane_slam_campus_test.cpp covers those).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>

#include "campus_plane_world.hpp"
#include "plane_world.hpp"
#include "sextant/filters/filter.hpp"
#include "sextant/filters/yaml.hpp"

namespace sextant {
namespace {

double xy_error(const Eigen::VectorXd& pose, const Pose6& truth) {
  return (pose.head<2>() - Eigen::Vector2d(truth.x, truth.y)).norm();
}

// Every landmark kept on this stretch is a vertical façade (no roof reaches kMinPoints), so z is
// not observed directly: the filters get it from the vehicle model (4.72) through the attitude,
// whose roll and pitch the façade normals do observe, while the 2D odometry keeps the start
// attitude. Both the 3D and the xy (fully observed) errors are asserted.
TEST(PlaneSlamTrueLandmarks, FiltersEndWellBelowOdometryOnCampus) {
  const test::PlaneWorld world = test::campus_world(test::kCampusScans, 3);
  const Pose6& odometry_end = world.odometry.back();
  const double odometry_error = test::position_error(odometry_end.vector(), world.truth.back());
  const double odometry_xy = xy_error(odometry_end.vector(), world.truth.back());
  std::size_t observations = 0;
  for (const SlamStepInput& s : world.steps) observations += s.observations.size();
  std::printf(
      "[plane-slam-true] campus seed 11, %zu scans, %zu true landmarks, %zu observations (>= %zu points)\n",
      test::kCampusScans, world.planes.size(), observations, test::kCampusMinPoints);
  std::printf("[plane-slam-true] odometry  final position error %.3f m (xy %.3f m)\n", odometry_error,
              odometry_xy);
  auto model = std::make_shared<PlaneSlamModel>();
  for (const std::string name : {"ekf", "ukf", "ckf"}) {
    auto filter = make_filter(name, model);
    const auto known = test::start_plane_slam(*filter, world);
    const SlamRunResult run = run_slam(*filter, world.steps, world.Q, world.R, {}, known);
    double worst = 0.0;
    for (std::size_t k = 0; k < run.steps.size(); ++k)
      worst = std::max(worst, test::position_error(run.steps[k].pose, world.truth[k + 1]));
    const double final_error = test::position_error(run.steps.back().pose, world.truth.back());
    std::printf(
        "[plane-slam-true] %-9s final position error %.3f m (xy %.3f m, worst along the run %.3f m), ratio "
        "to "
        "odometry %.3f, failed steps %zu\n",
        name.c_str(), final_error, xy_error(run.steps.back().pose, world.truth.back()), worst,
        final_error / odometry_error, run.failed_steps);
    EXPECT_EQ(run.failed_steps, 0u) << name;
    EXPECT_LT(final_error, 0.3 * odometry_error) << name;
    EXPECT_LT(xy_error(run.steps.back().pose, world.truth.back()), 0.3 * odometry_xy) << name;
    EXPECT_EQ(filter->num_landmarks(), static_cast<int>(world.planes.size())) << name;
  }
}

}  // namespace
}  // namespace sextant
