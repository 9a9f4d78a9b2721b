// FbML-NDT fails safe (issue 14): a feature sample that cannot constrain all six pose parameters —
// the ground alone, a corridor, two walls — is detected, and GBS points are added (or used instead),
// with the fallback recorded in the result. A well-conditioned scene keeps the thesis' sample.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/matchers/fbmlndt_matcher.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/yaml.hpp"
#include "sextant_test/random_draws.hpp"
#include "synthetic_scene.hpp"

namespace sextant {
namespace {

test::Scene ground_only() {
  test::Scene s;
  return s;
}

/// Two parallel walls 4 m apart along x and the ground between them: the planes cannot fix the
/// motion along the corridor.
test::Scene corridor() {
  test::Scene s;
  s.walls = {{{-20, 2, 0}, {1, 0, 0}, 40, 4}, {{-20, -2, 0}, {1, 0, 0}, 40, 4}};
  return s;
}

/// The corridor seen from `sensor_pose`, with four tree crowns (Gaussian blobs, σ = 0.25 m, 2.5 m up)
/// in it: no cell plane takes them, but they fix the motion along the corridor.
PointCloud corridor_with_shrubs(const Eigen::Isometry3d& sensor_pose, Rng& rng) {
  PointCloud cloud = test::sample_scene(corridor(), sensor_pose, rng, 20.0, 10.0, 0);
  const Eigen::Isometry3d to_sensor = sensor_pose.inverse();
  for (const Eigen::Vector3d& centre : {Eigen::Vector3d(-9, 0.3, 2.5), Eigen::Vector3d(-3, -0.3, 2.5),
                                        Eigen::Vector3d(3, 0.2, 2.5), Eigen::Vector3d(9, -0.2, 2.5)}) {
    for (int i = 0; i < 1500; ++i) {
      const Eigen::Vector3d d = test::normal_draws<3>(rng, 0.25);
      cloud.push_back((to_sensor * (centre + d)).cast<float>());
    }
  }
  return cloud;
}

/// Two perpendicular walls and no ground: nothing fixes the height.
test::Scene two_walls() {
  test::Scene s;
  s.walls = {{{-10, 8, 0}, {1, 0, 0}, 20, 6}, {{8, -10, 0}, {0, 1, 0}, 20, 6}};
  s.ground_half_extent = 0.0;
  return s;
}

ConstraintCheck check_of(const test::Scene& scene) {
  Rng rng(4);
  const PointCloud cloud = test::sample_scene(scene, test::sensor_pose(0, 0, 1.5, 0), rng, 20.0, 10.0, 300);
  Rng ransac(1);
  const PlaneExtraction planes = extract_cell_planes(cloud, PlaneExtractionSettings{}, ransac);
  return check_plane_constraints(planes.cell_planes, cloud, ConstraintThresholds{});
}

TEST(SampleConstraints, DegenerateScenesAreDetected) {
  for (const auto& [name, scene] : {std::pair{"ground only", ground_only()},
                                    std::pair{"corridor", corridor()}, std::pair{"two walls", two_walls()}}) {
    const ConstraintCheck c = check_of(scene);
    std::printf("%-11s %zu planes, %zu inliers, normal spread %.2g, information ratio %.2g: %s\n", name,
                c.planes, c.inliers, c.normal_spread[0], c.information_ratio, c.reason.c_str());
    EXPECT_FALSE(c.constrains_all) << name;
    EXPECT_LT(c.normal_spread[0], 0.01) << name;
    EXPECT_FALSE(c.reason.empty()) << name;
  }
  // The corridor's weakest direction is the translation along it (x).
  const ConstraintCheck c = check_of(corridor());
  EXPECT_GT(std::abs(c.weakest_direction[0]), 0.9);
}

TEST(SampleConstraints, TheCourtyardConstrainsEveryParameter) {
  const ConstraintCheck c = check_of(test::courtyard());
  EXPECT_TRUE(c.constrains_all) << c.reason;
  EXPECT_GT(c.normal_spread[0], 0.05);
  EXPECT_GT(c.information_ratio, 1e-2);
}

/// fbmlndt on a corridor pair displaced 0.6 m along the corridor, from the identity (denser fallback GBS).
RegistrationResult corridor_registration(const std::string& fallback, bool verify = false) {
  Rng rng(9);
  const PointCloud reference = corridor_with_shrubs(test::sensor_pose(0, 0, 1.5, 0), rng);
  const PointCloud input = corridor_with_shrubs(test::sensor_pose(0.6, 0, 1.5, 0), rng);
  auto matcher =
      make_matcher("fbmlndt",
                   YAML::Load("{fallback: " + fallback + ", verify: " + (verify ? "true" : "false") +
                              ", solver: lm, fallback_gbs: {cell_size: 0.5, max_per_cell: 10}}"),
                   "t.yaml");
  matcher->set_reference(reference);
  return matcher->align(input, Eigen::Isometry3d::Identity());
}

TEST(Fbmlndt, FallsBackToGbsPointsOnADegenerateCorridor) {
  const RegistrationResult thesis = corridor_registration("none");
  const RegistrationResult safe = corridor_registration("add_gbs");
  const RegistrationResult gbs = corridor_registration("gbs");
  std::printf("corridor, 0.6 m along x: none %.3f m, add_gbs %.3f m, gbs %.3f m\n  %s\n",
              thesis.T.translation().x(), safe.T.translation().x(), gbs.T.translation().x(),
              safe.summary().c_str());
  EXPECT_TRUE(thesis.fallback.empty());
  EXPECT_NE(safe.fallback.find("feature sample degenerate"), std::string::npos) << safe.fallback;
  EXPECT_NE(safe.fallback.find("added"), std::string::npos) << safe.fallback;
  EXPECT_NE(gbs.fallback.find("GBS points"), std::string::npos) << gbs.fallback;
  EXPECT_GT(safe.input_points, thesis.input_points);
  // The feature sample slides along the corridor (measured: stays at 0.01 m); matched alone, the GBS
  // sample's shrubs fix the motion (measured 0.53 m); added to the planes they pull it part of the way
  // (0.45 m), which is why `gbs` is the default fallback.
  EXPECT_LT(thesis.T.translation().x(), 0.1);
  EXPECT_NEAR(gbs.T.translation().x(), 0.6, 0.1);
  EXPECT_GT(safe.T.translation().x(), thesis.T.translation().x() + 0.2);
}

// Without the constraint fallback, the check on GBS points (verify) still catches the slide: the
// feature sample's pose (0.01 m) is refined on the GBS sample, whose shrubs fix the 0.6 m motion.
TEST(Fbmlndt, VerifyOnGbsPointsCatchesTheCorridorSlide) {
  const RegistrationResult slid = corridor_registration("none");
  const RegistrationResult verified = corridor_registration("none", true);
  EXPECT_LT(slid.T.translation().x(), 0.1);
  EXPECT_NEAR(verified.T.translation().x(), 0.6, 0.1) << verified.summary();
  EXPECT_NE(verified.fallback.find("GBS"), std::string::npos) << verified.fallback;
}

TEST(Fbmlndt, WellConstrainedScenesKeepTheFeatureSample) {
  Rng rng(21);
  const PointCloud reference =
      test::sample_scene(test::courtyard(), test::sensor_pose(0, 0, 1.5, 0), rng, 6.0, 2.0, 200);
  const PointCloud input =
      test::sample_scene(test::courtyard(), test::sensor_pose(0.4, -0.3, 1.5, 4.0), rng, 6.0, 2.0, 200);
  auto matcher = make_matcher("fbmlndt", YAML::Load("seed: 5"), "t.yaml");
  matcher->set_reference(reference);
  const RegistrationResult r = matcher->align(input, Eigen::Isometry3d::Identity());
  EXPECT_TRUE(r.fallback.empty()) << r.fallback;
}

TEST(Fbmlndt, FallbackSettingsAreValidated) {
  EXPECT_THROW(make_matcher("fbmlndt", YAML::Load("fallback: sometimes"), "t.yaml"), InputError);
  EXPECT_THROW(make_matcher("fbmlndt", YAML::Load("constraints: {min_normal_spread: 0.5}"), "t.yaml"),
               InputError);
  EXPECT_THROW(make_matcher("fbmlndt", YAML::Load("constraints: {min_planez: 3}"), "t.yaml"), InputError);
  EXPECT_THROW(make_matcher("fbmlndt", YAML::Load("fallback_gbs: {cell_size: -1}"), "t.yaml"), InputError);
  EXPECT_NO_THROW(
      make_matcher("fbmlndt", YAML::Load("{fallback: gbs, fallback_gbs: {cell_size: 0.5}}"), "t.yaml"));
}

}  // namespace
}  // namespace sextant
