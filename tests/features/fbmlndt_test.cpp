// FbML-NDT (Table 3.2): the fbs sampler keeps plane inliers only, and fbmlndt recovers a known
// transform between two synthetic scans of the courtyard.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/matchers/fbmlndt_matcher.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/sampler.hpp"
#include "sextant/matchers/yaml.hpp"
#include "synthetic_scene.hpp"

namespace sextant {
namespace {

TEST(FeatureBasedSampler, SelectsPlaneInliersOnly) {
  Rng rng(3);
  const PointCloud cloud =
      test::sample_scene(test::courtyard(), test::sensor_pose(0, 0, 1.5, 0), rng, 4.0, 1.0, 300);
  const auto sampler = make_sampler("fbs", YAML::Load("cell_size: 2.0"), "t.yaml");
  EXPECT_EQ(sampler->name(), "fbs");
  Rng a(1), b(1);
  const auto selected = sampler->select(cloud, a);
  EXPECT_EQ(selected, sampler->select(cloud, b));  // deterministic
  ASSERT_FALSE(selected.empty());
  EXPECT_TRUE(std::is_sorted(selected.begin(), selected.end()));
  EXPECT_LT(selected.size(), cloud.size());
  // Blob points (the last 5 × 300) are rarely plane inliers.
  const std::size_t blob_begin = cloud.size() - 1500;
  const auto blob_selected =
      std::count_if(selected.begin(), selected.end(), [&](std::size_t i) { return i >= blob_begin; });
  const double blob_share = double(blob_selected) / 1500.0,
               overall = double(selected.size()) / double(cloud.size());
  std::printf("fbs keeps %.0f %% of the scan and %.0f %% of the clutter blobs\n", 100 * overall,
              100 * blob_share);
  EXPECT_LT(blob_share, 0.5 * overall);
  EXPECT_THROW(make_sampler("fbs", YAML::Load("cell_sise: 2"), "t.yaml"), InputError);
}

TEST(Fbmlndt, RecoversAKnownTransformOnASyntheticPair) {
  const test::Scene scene = test::courtyard();
  const Eigen::Isometry3d reference_pose = test::sensor_pose(0, 0, 1.5, 0),
                          input_pose = test::sensor_pose(0.4, -0.3, 1.5, 4.0);
  Rng rng(21);
  const PointCloud reference = test::sample_scene(scene, reference_pose, rng, 6.0, 2.0, 200);
  const PointCloud input = test::sample_scene(scene, input_pose, rng, 6.0, 2.0, 200);
  const Eigen::Isometry3d truth = reference_pose.inverse() * input_pose;  // p_ref = truth · p_input

  auto matcher = make_matcher("fbmlndt", YAML::Load("seed: 5\nfeatures: {cell_size: 2.0}"), "t.yaml");
  EXPECT_EQ(matcher->name(), "fbmlndt");
  matcher->set_reference(reference);
  const RegistrationResult r = matcher->align(input, Eigen::Isometry3d::Identity());
  const Eigen::Isometry3d error = truth.inverse() * r.T;
  std::printf("fbmlndt: %s; %zu of %zu input points matched; error %.3f m, %.3f deg\n", r.summary().c_str(),
              r.input_points, input.size(), translation_norm(error), rotation_angle(error) * 180.0 / M_PI);
  EXPECT_LT(r.input_points, input.size());
  EXPECT_GT(r.input_points, input.size() / 4);
  EXPECT_LT(translation_norm(error), 0.05);
  EXPECT_LT(rotation_angle(error) * 180.0 / M_PI, 0.5);
}

TEST(Fbmlndt, InputWithoutPlanesIsAResultNotACrash) {
  auto matcher = make_matcher("fbmlndt");
  Rng rng(2);
  PointCloud reference =
      test::sample_scene(test::courtyard(), Eigen::Isometry3d::Identity(), rng, 2.0, 0.5, 50);
  matcher->set_reference(reference);
  const RegistrationResult r = matcher->align(PointCloud(), Eigen::Isometry3d::Identity());
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.input_points, 0u);
}

}  // namespace
}  // namespace sextant
