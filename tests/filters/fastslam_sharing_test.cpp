// FastSLAM's shared map (landmark_map.hpp) inside the filter: resampling copies no landmark and
// no tree node, a later update copies only the observed landmarks' paths, and it never changes
// what a sibling particle (sharing the same landmark objects) sees. Plus log weights under an
// impossible observation and a heavy-tailed odometry step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <set>

#include "plane_world.hpp"
#include "sextant/filters/fastslam.hpp"
#include "sextant_test/random_draws.hpp"

namespace sextant {
namespace {

constexpr int kParticles = 50;
constexpr int kLandmarks = 60;  // depth 2 of the 8-ary tree (8 < 60 ≤ 64)

const Eigen::Matrix4d kR = Eigen::Vector4d(1e-4, 1e-4, 1e-4, 1e-4).asDiagonal();

Eigen::Vector4d random_plane(Rng& rng) {
  const double d = rng.uniform(1.0, 20.0);
  const Eigen::Vector3d n = test::normal_draws<3>(rng);
  return test::plane(n.x(), n.y(), n.z(), d);
}

/// A filter whose particles are spread by 1 m around the origin, with kLandmarks landmarks known
/// exactly in the world (so the particles disagree on where they see them from).
std::unique_ptr<FastSlam> spread_filter(std::vector<Eigen::Vector4d>& planes,
                                        double resample_threshold = 0.5) {
  auto filter = std::make_unique<FastSlam>(std::make_shared<PlaneSlamModel>(),
                                           FastSlamSettings{kParticles, resample_threshold}, 4);
  Rng rng(8);
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(6 + 4 * kLandmarks);
  Eigen::VectorXd sigma = Eigen::VectorXd::Constant(x0.size(), 1e-3);
  sigma.head(3).setConstant(1.0);
  sigma.segment(3, 3).setConstant(1e-3);
  for (int j = 0; j < kLandmarks; ++j) {
    planes.push_back(random_plane(rng));
    x0.segment<4>(6 + 4 * j) = planes.back();
  }
  EXPECT_TRUE(filter->initialize(x0, sigma.array().square().matrix().asDiagonal()).ok());
  return filter;
}

TEST(FastSlamSharing, ResamplingCopiesNoLandmarkAndUpdatesCopyOnlyObservedPaths) {
  std::vector<Eigen::Vector4d> planes;
  auto filter = spread_filter(planes);
  const MapCounters built = filter->counters().map;
  EXPECT_EQ(built.landmarks_written, static_cast<std::size_t>(kParticles * kLandmarks));

  // 1. Forced resampling: N particles copied, not one landmark or node.
  filter->resample();
  EXPECT_EQ(filter->counters().particle_copies, static_cast<std::size_t>(kParticles));
  EXPECT_EQ(filter->counters().map.landmarks_written, built.landmarks_written);
  EXPECT_EQ(filter->counters().map.nodes_copied, built.nodes_copied);

  // 2. An observation of landmark 3 from the origin: the particles (spread by 1 m) disagree,
  //    N_eff collapses and update() resamples. The update itself writes one landmark per
  //    particle and copies its path (depth 2); the resampling adds nothing.
  const MapCounters before = filter->counters().map;
  const std::size_t resamplings = filter->counters().resamplings;
  const Eigen::VectorXd origin = Eigen::VectorXd::Zero(6);
  ASSERT_TRUE(filter->update({PlaneSlamModel().observe(origin, planes[3])}, kR, {3}).ok());
  EXPECT_EQ(filter->counters().resamplings, resamplings + 1);
  EXPECT_EQ(filter->counters().map.landmarks_written - before.landmarks_written,
            static_cast<std::size_t>(kParticles));
  EXPECT_EQ(filter->counters().map.nodes_copied - before.nodes_copied,
            static_cast<std::size_t>(2 * kParticles));
  std::printf(
      "[fastslam-sharing] %d particles x %d landmarks: built %zu landmark EKFs / %zu nodes; forced "
      "resampling copied 0 / 0; one update + resampling wrote %zu / %zu\n",
      kParticles, kLandmarks, built.landmarks_written, built.nodes_copied,
      filter->counters().map.landmarks_written - before.landmarks_written,
      filter->counters().map.nodes_copied - before.nodes_copied);

  // After resampling the survivors share their source's landmark objects.
  const std::vector<FastSlamParticle>& particles = filter->particles();
  std::set<const LandmarkEkf*> distinct;
  for (const FastSlamParticle& p : particles) distinct.insert(p.map.share(3).get());
  EXPECT_LT(distinct.size(), static_cast<std::size_t>(kParticles));
}

TEST(FastSlamSharing, AParticlesUpdateDoesNotChangeItsSiblingsLandmarks) {
  std::vector<Eigen::Vector4d> planes;
  auto filter = spread_filter(planes);
  const Eigen::VectorXd origin = Eigen::VectorXd::Zero(6);
  ASSERT_TRUE(filter->update({PlaneSlamModel().observe(origin, planes[3])}, kR, {3}).ok());  // resamples
  // Siblings: particles sharing landmark 5's object. Snapshot its value, then update landmark 5.
  const std::vector<FastSlamParticle> snapshot = filter->particles();
  const std::shared_ptr<const LandmarkEkf> shared = snapshot[0].map.share(5);
  int siblings = 0;
  for (const FastSlamParticle& p : snapshot) siblings += p.map.share(5) == shared;
  ASSERT_GE(siblings, 2);
  const LandmarkEkf value = *shared;
  ASSERT_TRUE(filter->predict(Eigen::VectorXd::Zero(6), Eigen::MatrixXd::Identity(6, 6) * 1e-4).ok());
  Eigen::Vector4d z = PlaneSlamModel().observe(origin, planes[5]);
  z[3] += 0.3;  // an update that moves the landmark
  ASSERT_TRUE(filter->update({z}, kR, {5}).ok());
  // The shared object is untouched; each particle now holds its own landmark 5, changed.
  EXPECT_EQ(shared->mean, value.mean);
  EXPECT_EQ(shared->covariance, value.covariance);
  std::set<const LandmarkEkf*> unobserved;
  for (const FastSlamParticle& p : snapshot) unobserved.insert(p.map.share(7).get());
  std::set<const LandmarkEkf*> now;
  for (const FastSlamParticle& p : filter->particles()) {
    now.insert(p.map.share(5).get());
    EXPECT_NE(p.map.share(5), shared);
    EXPECT_GT((p.map.get(5).mean - value.mean).norm(), 1e-6);
    EXPECT_EQ(unobserved.count(p.map.share(7).get()), 1u);  // unobserved: still a shared object
  }
  EXPECT_EQ(now.size(), static_cast<std::size_t>(kParticles));
}

// An observation thousands of σ from every particle's prediction: every likelihood underflows
// exp(), but the log weights normalise to finite weights summing to 1 and the estimate stays
// finite. Resampling is off: it would reset the weights to 1/N and hide a broken normalisation.
TEST(FastSlamSharing, ImpossibleObservationLeavesFiniteWeights) {
  std::vector<Eigen::Vector4d> planes;
  auto filter = spread_filter(planes, 0.0);
  Eigen::Vector4d z = PlaneSlamModel().observe(Eigen::VectorXd::Zero(6), planes[0]);
  z[3] += 500.0;  // 50 000 σ
  const StepResult r = filter->update({z}, kR, {0});
  EXPECT_TRUE(r.ok()) << to_string(r.status);
  double sum = 0.0;
  for (double w : filter->weights()) {
    EXPECT_TRUE(std::isfinite(w));
    sum += w;
  }
  EXPECT_NEAR(sum, 1.0, 1e-9);
  EXPECT_TRUE(filter->mean().allFinite());
  EXPECT_TRUE(filter->covariance().allFinite());
}

// A heavy-tailed odometry step (a 5 m, 30° jump that Q says is 40 σ away) on the plane world:
// the filter keeps running with finite weights and estimates and reports no failure.
TEST(FastSlamSharing, HeavyTailedOdometryStepDoesNotBreakTheFilter) {
  test::PlaneWorld world = test::make_plane_world(30, 5);
  world.steps[10].u[0] += 5.0;
  world.steps[10].u[5] += 0.5;
  FastSlam filter(std::make_shared<PlaneSlamModel>(), {50, 0.5}, 6);
  const auto known = test::start_plane_slam(filter, world);
  const SlamRunResult run = run_slam(filter, world.steps, world.Q, world.R, {}, known);
  EXPECT_EQ(run.failed_steps, 0u);
  for (const SlamStepRecord& step : run.steps) EXPECT_TRUE(step.pose.allFinite());
  for (double w : filter.weights()) EXPECT_TRUE(std::isfinite(w));
  std::printf("[fastslam-heavy-tail] after a 5 m / 0.5 rad odometry outlier: final position error %.2f m\n",
              test::position_error(run.steps.back().pose, world.truth.back()));
}

}  // namespace
}  // namespace sextant
