// FastSLAM 2.0 on the synthetic campus with true plane landmarks and true association
// (campus_plane_world.hpp), against the EKF on the same data: with 50 particles its position
// error along the first 50 scans must be comparable to the EKF's, and well below odometry's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "campus_plane_world.hpp"
#include "sextant/filters/fastslam.hpp"

namespace sextant {
namespace {

struct RunErrors {
  double mean = 0.0;   ///< mean position error over the run [m]
  double final = 0.0;  ///< at the last scan [m]
};

RunErrors errors_of(const SlamRunResult& run, const test::PlaneWorld& world) {
  RunErrors e;
  for (std::size_t k = 0; k < run.steps.size(); ++k)
    e.mean +=
        test::position_error(run.steps[k].pose, world.truth[k + 1]) / static_cast<double>(run.steps.size());
  e.final = test::position_error(run.steps.back().pose, world.truth.back());
  return e;
}

TEST(FastSlamCampus, FiftyParticlesReachAPoseErrorComparableToTheEkf) {
  const test::PlaneWorld world = test::campus_world(test::kCampusScans, 3);
  auto model = std::make_shared<PlaneSlamModel>();
  double odometry_mean = 0.0;
  for (std::size_t k = 1; k < world.truth.size(); ++k)
    odometry_mean += test::position_error(world.odometry[k].vector(), world.truth[k]) /
                     static_cast<double>(world.truth.size() - 1);

  auto ekf = default_filter("ekf")(model);
  const SlamRunResult ekf_run =
      run_slam(*ekf, world.steps, world.Q, world.R, {}, test::start_plane_slam(*ekf, world));
  const RunErrors ekf_error = errors_of(ekf_run, world);
  ASSERT_EQ(ekf_run.failed_steps, 0u);
  std::printf(
      "[fastslam-campus] %zu scans, %zu landmarks: odometry mean error %.3f m; EKF mean %.3f m, final %.3f "
      "m\n",
      test::kCampusScans, world.planes.size(), odometry_mean, ekf_error.mean, ekf_error.final);

  // Eight filter seeds on the same data. Measured (seeds 1–8): 0.78–2.28 × the EKF's mean error,
  // median 1.18, mean 1.30; with 200 particles 0.73–1.29 ×, mean 0.94 (not run here).
  std::vector<double> ratios;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    FastSlam fastslam(model, {50, 0.5}, seed);
    const SlamRunResult run =
        run_slam(fastslam, world.steps, world.Q, world.R, {}, test::start_plane_slam(fastslam, world));
    const RunErrors error = errors_of(run, world);
    ratios.push_back(error.mean / ekf_error.mean);
    std::printf(
        "[fastslam-campus] FastSLAM 2.0, 50 particles, seed %llu: mean %.3f m (%.2f x EKF), final %.3f m, "
        "resamplings %zu, landmark EKFs written %zu\n",
        static_cast<unsigned long long>(seed), error.mean, ratios.back(), error.final,
        fastslam.counters().resamplings, fastslam.counters().map.landmarks_written);
    EXPECT_EQ(run.failed_steps, 0u) << seed;
    EXPECT_EQ(fastslam.num_landmarks(), static_cast<int>(world.planes.size()));
    EXPECT_LT(error.mean, 0.5 * odometry_mean) << seed;  // every run well below odometry
    EXPECT_LT(ratios.back(), 3.0) << seed;               // no run far from the EKF
  }
  // Comparable to the EKF: the median run within 1.5 × the EKF's mean error on the same data.
  std::nth_element(ratios.begin(), ratios.begin() + 4, ratios.end());
  EXPECT_LT(ratios[4], 1.5);
}

}  // namespace
}  // namespace sextant
