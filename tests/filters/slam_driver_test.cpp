// The SLAM driver (slam_runner.hpp) against the filter called by hand, its per-step callback, and
// Filter::diagnostics() of the information filters (what the plane-SLAM experiments record).
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "plane_world.hpp"
#include "sextant/filters/eseif.hpp"
#include "sextant/filters/gaussian_filters.hpp"
#include "sextant/filters/plane_slam_model.hpp"
#include "sextant/filters/seif.hpp"
#include "sextant/filters/slam_runner.hpp"

namespace sextant {
namespace slam_driver_test {

double max_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() ? (a - b).cwiseAbs().maxCoeff() : 1e300;
}

/// Step 0 observes at the start without a motion update (empty u); then the world's steps.
std::vector<SlamStepInput> steps_of(const test::PlaneWorld& world) {
  std::vector<SlamStepInput> steps(1);
  for (std::size_t i = 0; i < world.first_observations.size(); ++i)
    steps[0].observations.push_back({world.first_observations[i], static_cast<int>(i)});
  steps.insert(steps.end(), world.steps.begin(), world.steps.end());
  return steps;
}

TEST(SlamDriver, EkfGivesTheStatesOfTheFilterCalledByHandAndCallsBackOncePerStep) {
  const test::PlaneWorld world = test::make_plane_world(6, 11);
  const std::vector<SlamStepInput> steps = steps_of(world);
  const auto model = std::make_shared<PlaneSlamModel>();
  const Eigen::MatrixXd P0 = Eigen::MatrixXd::Identity(6, 6) * 1e-6;

  Ekf driven(model);
  driven.initialize(world.truth[0].vector(), P0);
  std::vector<std::size_t> indices;
  std::vector<Eigen::VectorXd> states;
  const SlamRunResult run = run_slam(driven, steps, world.Q, world.R, {}, {},
                                     [&](std::size_t k, const SlamStepRecord& record, const Filter& filter) {
                                       indices.push_back(k);
                                       states.push_back(filter.mean());
                                       EXPECT_EQ(max_difference(record.pose, filter.pose()), 0.0);
                                     });

  Ekf by_hand(model);
  by_hand.initialize(world.truth[0].vector(), P0);
  for (const Eigen::VectorXd& z : world.first_observations) by_hand.augment(z, world.R);
  ASSERT_EQ(states.size(), steps.size());
  EXPECT_EQ(max_difference(states[0], by_hand.mean()), 0.0) << "step 0 must not predict";
  for (std::size_t k = 0; k < world.steps.size(); ++k) {
    by_hand.predict(world.steps[k].u, world.Q);
    std::vector<Eigen::VectorXd> zs;
    std::vector<int> associations;
    for (const SlamObservation& o : world.steps[k].observations) {
      zs.push_back(o.z);
      associations.push_back(o.landmark);
    }
    by_hand.update(zs, world.R, associations);
    EXPECT_EQ(max_difference(states[k + 1], by_hand.mean()), 0.0) << "step " << k + 1;
  }
  ASSERT_EQ(indices.size(), steps.size());
  for (std::size_t k = 0; k < indices.size(); ++k) EXPECT_EQ(indices[k], k);
  EXPECT_EQ(run.steps.size(), steps.size());
  EXPECT_EQ(run.steps.front().augmented, world.first_observations.size());
  EXPECT_EQ(run.failed_steps, 0u);
}

/// Runs an information filter over the world and returns its diagnostics(), which must point at Ω.
template <class InformationFilter>
FilterDiagnostics diagnostics_after_run(InformationFilter& filter, const test::PlaneWorld& world) {
  run_slam(filter, world.steps, world.Q, world.R, {}, test::start_plane_slam(filter, world));
  const FilterDiagnostics d = static_cast<const Filter&>(filter).diagnostics();
  EXPECT_EQ(d.information, &filter.information());
  return d;
}

TEST(SlamDriver, DiagnosticsReportTheInformationMatrixAndRelocations) {
  const test::PlaneWorld world = test::make_plane_world(8, 5);
  const auto model = std::make_shared<PlaneSlamModel>();
  SeifSettings seif_settings;
  seif_settings.max_active_landmarks = 4;
  Seif seif("seif", model, seif_settings);
  const FilterDiagnostics d = diagnostics_after_run(seif, world);
  ASSERT_NE(d.information, nullptr);
  EXPECT_TRUE(d.approximate_covariance);
  EXPECT_EQ(d.information->neighbours(0).size(), seif.active_landmarks().size());
  EXPECT_LE(d.information->neighbours(0).size(), 4u);  // sparsified
  EXPECT_EQ(d.relocations, 0u);

  EseifSettings eseif_settings;
  eseif_settings.max_active_landmarks = 4;
  Eseif eseif("eseif", model, eseif_settings);
  const FilterDiagnostics e = diagnostics_after_run(eseif, world);
  EXPECT_FALSE(e.approximate_covariance);  // ESEIF's joint_covariance is its exact marginal
  EXPECT_EQ(e.relocations, eseif.relocations());
  EXPECT_EQ(e.skipped_relocations, eseif.skipped_relocations());
  EXPECT_GT(e.relocations + e.skipped_relocations, 0u);

  Ekf ekf(model);
  ekf.initialize(world.truth[0].vector(), Eigen::MatrixXd::Identity(6, 6) * 1e-6);
  const FilterDiagnostics m = static_cast<const Filter&>(ekf).diagnostics();
  EXPECT_EQ(m.information, nullptr);
  EXPECT_FALSE(m.approximate_covariance);
}

}  // namespace slam_driver_test
}  // namespace sextant
