// SEIF: constant-cost measurement and motion updates, bounded active set, EIF equivalence.
#include <gtest/gtest.h>

#include "plane_world.hpp"
#include "sextant/filters/seif.hpp"
#include "sextant/filters/yaml.hpp"

namespace sextant {
namespace {

struct Costs {
  std::size_t update = 0, predict = 0;
};

// Builds a map of `landmarks` random planes, then measures one motion and one measurement update.
Costs costs_with_map(int landmarks, int max_active) {
  auto model = std::make_shared<PlaneSlamModel>();
  SeifSettings s;
  s.max_active_landmarks = max_active;
  Seif seif("seif", model, s);
  test::grow_random_plane_map(seif, landmarks, 3);
  EXPECT_LE(static_cast<int>(seif.active_landmarks().size()), max_active);
  EXPECT_EQ(seif.information().neighbours(0).size(), seif.active_landmarks().size());
  Costs c;
  Eigen::VectorXd u(6);
  u << 0.5, 0.0, 0.0, 0.0, 0.0, 0.01;
  EXPECT_TRUE(seif.predict(u, Eigen::MatrixXd::Identity(6, 6) * 1e-4).ok());
  c.predict = seif.last_step_touched();
  const int observed = landmarks - 1;  // an active landmark
  const Eigen::VectorXd z =
      model->observe(seif.pose(), seif.mean().segment(landmark_offset(*model, observed), 4));
  EXPECT_TRUE(seif.update({z}, Eigen::Vector4d(1e-4, 1e-4, 1e-4, 1e-2).asDiagonal(), {observed}).ok());
  c.update = seif.last_step_touched();
  return c;
}

TEST(Seif, UpdateCostIndependentOfMapSize) {
  const Costs small = costs_with_map(20, 4), large = costs_with_map(120, 4);
  std::printf("[seif] touched entries: update %zu (20 planes) vs %zu (120 planes); predict %zu vs %zu\n",
              small.update, large.update, small.predict, large.predict);
  EXPECT_LE(large.update, small.update * 3 / 2);
  EXPECT_LE(large.predict, small.predict * 3 / 2);
}

TEST(Seif, SparsificationKeepsTheActiveSetBoundedAndCutsPoseLinks) {
  const test::PlaneWorld world = test::make_plane_world(15, 2);
  auto model = std::make_shared<PlaneSlamModel>();
  SeifSettings s;
  s.max_active_landmarks = 3;
  Seif seif("seif", model, s);
  const auto known = test::start_plane_slam(seif, world);
  EXPECT_LE(seif.active_landmarks().size(), 3u);
  const SlamRunResult run = run_slam(seif, world.steps, world.Q, world.R, {}, known);
  EXPECT_EQ(run.failed_steps, 0u);
  EXPECT_LE(seif.active_landmarks().size(), 3u);
  EXPECT_EQ(seif.information().neighbours(0).size(), seif.active_landmarks().size());
  // The approximation still localises: well below the odometry error.
  const double error = test::position_error(seif.pose(), world.truth.back());
  const double odometry = test::position_error(world.odometry.back().vector(), world.truth.back());
  std::printf("[seif] max 3 active: final position error %.3f m, odometry %.3f m\n", error, odometry);
  EXPECT_LT(error, 0.5 * odometry);
}

TEST(Seif, WithoutSparsificationEqualsTheEif) {
  const test::PlaneWorld world = test::make_plane_world(10, 4);
  auto model = std::make_shared<PlaneSlamModel>();
  SeifSettings off;
  off.max_active_landmarks = 0;
  off.mean_recovery = "exact";
  Seif seif("seif", model, off);
  auto eif = make_filter("eif", model);
  const auto k1 = test::start_plane_slam(seif, world);
  const auto k2 = test::start_plane_slam(*eif, world);
  run_slam(seif, world.steps, world.Q, world.R, {}, k1);
  run_slam(*eif, world.steps, world.Q, world.R, {}, k2);
  EXPECT_LT((seif.mean() - eif->mean()).norm(), 1e-12);
  EXPECT_EQ(seif.active_landmarks().size(), world.planes.size());
}

}  // namespace
}  // namespace sextant
