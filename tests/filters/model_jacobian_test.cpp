// Every analytic Jacobian of the SLAM models against central finite differences.
#include <functional>

#include <gtest/gtest.h>

#include "sextant/core/rng.hpp"
#include "sextant/filters/plane_slam_model.hpp"
#include "sextant/filters/range_bearing_model.hpp"
#include "sextant_test/finite_differences.hpp"
#include "sextant_test/random_draws.hpp"

namespace sextant {
namespace {

using test::central_jacobian;
using Fn = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

/// Central differences of f at x, with the given output entries wrapped as angles.
Eigen::MatrixXd numeric_jacobian(const Fn& f, const Eigen::VectorXd& x,
                                 const std::vector<int>& output_angles = {}) {
  return central_jacobian(f, x, 1e-6, [&](Eigen::VectorXd& d) { wrap_entries(d, output_angles); });
}

void expect_near(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& numeric, const char* what) {
  test::expect_jacobian_near(analytic, numeric, 1e-6, what);
}

void check_model(const SlamModel& model, const Eigen::VectorXd& pose, const Eigen::VectorXd& u,
                 const Eigen::VectorXd& landmark) {
  const auto pa = model.pose_angles();
  const auto oa = model.observation_angles();
  expect_near(model.process_jacobian_pose(pose, u),
              numeric_jacobian([&](const Eigen::VectorXd& x) { return model.process(x, u); }, pose, pa),
              "F_x");
  expect_near(model.process_jacobian_control(pose, u),
              numeric_jacobian([&](const Eigen::VectorXd& v) { return model.process(pose, v); }, u, pa),
              "F_u");
  expect_near(
      model.observe_jacobian_pose(pose, landmark),
      numeric_jacobian([&](const Eigen::VectorXd& x) { return model.observe(x, landmark); }, pose, oa),
      "H_x");
  expect_near(
      model.observe_jacobian_landmark(pose, landmark),
      numeric_jacobian([&](const Eigen::VectorXd& m) { return model.observe(pose, m); }, landmark, oa),
      "H_m");
  const Eigen::VectorXd z = model.observe(pose, landmark);
  expect_near(model.augment_jacobian_pose(pose, z),
              numeric_jacobian([&](const Eigen::VectorXd& x) { return model.augment(x, z); }, pose), "G_v");
  expect_near(model.augment_jacobian_observation(pose, z),
              numeric_jacobian([&](const Eigen::VectorXd& v) { return model.augment(pose, v); }, z), "G_z");
  // g is the inverse of h: augmenting an observation gives back the landmark.
  EXPECT_LT((model.augment(pose, z) - landmark).norm(), 1e-9);
}

TEST(PlaneSlamModel, JacobiansMatchFiniteDifferences) {
  PlaneSlamModel model;
  Rng rng(7);
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::VectorXd pose(6), u(6), m(4);
    for (int i = 0; i < 6; ++i) pose[i] = rng.uniform(-1.0, 1.0) * (i < 3 ? 10.0 : 1.2);
    for (int i = 0; i < 6; ++i) u[i] = rng.uniform(-1.0, 1.0) * (i < 3 ? 2.0 : 0.2);
    m.head<3>() = test::normal_draws<3>(rng).normalized();
    m[3] = rng.uniform(-20.0, 20.0);
    check_model(model, pose, u, m);
  }
}

TEST(PlaneSlamModel, ObservationIsPlaneInRobotFrame) {
  // eq. (4.64) agrees with Plane::transformed (points p_L = T⁻¹ p_W).
  PlaneSlamModel model;
  const Pose6 pose{1.0, -2.0, 0.5, 0.1, -0.2, 0.7};
  Plane world;
  world.normal = Eigen::Vector3d(0.3, 0.4, 0.866).normalized();
  world.d = 4.0;
  const Plane local = world.transformed(inverse(to_isometry(pose)));
  const Eigen::VectorXd z = model.observe(pose.vector(), plane_vector(world));
  EXPECT_LT((z - plane_vector(local)).norm(), 1e-12);
}

TEST(PlaneSlamModel, OdometryIncrementInvertsTheVehicleModel) {
  PlaneSlamModel model;
  const Pose6 a{1, 2, 3, 0.1, 0.2, 3.0}, b{2, 1, 3.5, 0.15, 0.1, -3.0};
  const Eigen::VectorXd next = model.process(a.vector(), odometry_increment(a, b));
  EXPECT_LT(state_difference(model, next, b.vector()).norm(), 1e-12);
}

TEST(PlaneSlamModel, AlignAndNormalize) {
  PlaneSlamModel model;
  Eigen::VectorXd z(4), predicted(4), m(4);
  z << 0, 0, -1, -3;
  predicted << 0, 0.1, 1, 3;
  EXPECT_EQ(model.align_observation(z, predicted), -z);
  m << 0, 0, 2, 6;
  model.normalize_landmark(m);
  EXPECT_DOUBLE_EQ(m[2], 1.0);
  EXPECT_DOUBLE_EQ(m[3], 3.0);
}

TEST(RangeBearingModel, JacobiansMatchFiniteDifferences) {
  RangeBearingModel model;
  Rng rng(3);
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::VectorXd pose(3), u(2), m(2);
    pose << rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-3, 3);
    u << rng.uniform(0.5, 3), rng.uniform(-0.5, 0.5);
    m << rng.uniform(-30, 30), rng.uniform(-30, 30);
    check_model(model, pose, u, m);
  }
}

}  // namespace
}  // namespace sextant
