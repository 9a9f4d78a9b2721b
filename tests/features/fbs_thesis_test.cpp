// The thesis' feature sample (§3.3.1.1, Table 3.2; features/extraction.hpp thesis_feature_sampling):
// on a hand-built scan with known planes in known cells of the input's own split, the kept points are
// exactly the inliers of one plane per cell with more than 10 of them; and FbML-NDT on that sample
// alone recovers a known 2 m motion from a zero guess.
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/features/extraction.hpp"
#include "sextant/matchers/fbmlndt_matcher.hpp"
#include "sextant/matchers/sampler.hpp"
#include "sextant/matchers/yaml.hpp"
#include "synthetic_scene.hpp"

namespace sextant {
namespace {

/// A scan over the box [0, 8]³, whose split at layer 1 (q = 8) is 2 × 2 × 2 cells of 4 m. Per cell:
///   (0,0,0): 20 points on z = 0 and 5 scattered points off it → the 20
///   (1,0,0): 10 points on x = 5 → none (10 does not exceed 10)
///   (0,1,0): 11 points on y = 5 → all 11
///   (1,1,0): 30 points on z = 1 and 15 on x = 6 (a corner) → the 30 (one plane per cell)
///   (1,1,1): the box's far corner (8, 8, 8) alone → none
struct KnownScan {
  PointCloud cloud;
  std::set<std::size_t> thesis_keeps;  ///< indices the thesis rule selects
  std::set<std::size_t> second_plane;  ///< the corner's smaller plane (x = 6)
};

KnownScan known_scan() {
  KnownScan s;
  const auto add = [&](double x, double y, double z, bool kept) {
    if (kept) s.thesis_keeps.insert(s.cloud.size());
    s.cloud.push_back(Eigen::Vector3f(float(x), float(y), float(z)));
  };
  s.cloud.push_back(Eigen::Vector3f(0, 0, 0));  // on z = 0 in cell (0,0,0): the box's low corner
  s.thesis_keeps.insert(0);
  for (int i = 0; i < 19; ++i) add(0.5 + 0.15 * i, 0.4 + 0.7 * (i % 4), 0.0, true);
  const double clutter[5][3] = {
      {1.0, 1.0, 1.3}, {2.1, 0.6, 2.2}, {3.0, 2.5, 0.9}, {0.7, 3.2, 3.1}, {2.6, 1.8, 1.7}};
  for (const auto& c : clutter) add(c[0], c[1], c[2], false);
  for (int i = 0; i < 10; ++i) add(5.0, 0.5 + 0.3 * i, 0.5 + 0.25 * (i % 3) + 0.1 * i, false);
  for (int i = 0; i < 11; ++i) add(0.5 + 0.28 * i, 5.0, 0.4 + 0.3 * (i % 4), true);
  for (int i = 0; i < 30; ++i) add(4.3 + 0.1 * i, 4.3 + 0.12 * (i % 7) * 4, 1.0, true);
  for (int i = 0; i < 15; ++i) {
    s.second_plane.insert(s.cloud.size());
    add(6.0, 4.4 + 0.2 * i, 1.5 + 0.4 * (i % 5), false);
  }
  add(8.0, 8.0, 8.0, false);
  return s;
}

PlaneExtractionSettings thesis_at_layer_1() {
  PlaneExtractionSettings s = thesis_feature_sampling();
  s.split_layer = 1;  // 8 cells of 4 m over the 8 m box
  return s;
}

TEST(ThesisFeatureSampling, KeepsTheInliersOfOnePlanePerCellAboveTen) {
  const KnownScan scan = known_scan();
  Rng rng(7);
  const PlaneExtraction out = extract_cell_planes(scan.cloud, thesis_at_layer_1(), rng);
  EXPECT_NEAR(out.stats.cell_edge, 4.0, 1e-9);
  const std::vector<std::size_t> kept = out.cell_inlier_indices();
  EXPECT_EQ(std::set<std::size_t>(kept.begin(), kept.end()), scan.thesis_keeps);
  ASSERT_EQ(out.cell_planes.size(), 3u);
  std::multiset<std::size_t> per_plane;
  for (const auto& p : out.cell_planes) per_plane.insert(p.inliers.size());
  EXPECT_EQ(per_plane, (std::multiset<std::size_t>{11, 20, 30}));
}

TEST(ThesisFeatureSampling, DiffersFromTheDefaultWhereTheThesisRuleDoes) {
  const KnownScan scan = known_scan();
  PlaneExtractionSettings ours = thesis_at_layer_1();
  ours.max_planes_per_cell = 2;  // the default's two planes per cell: the corner's x = 6 is kept too
  Rng rng(7);
  const std::vector<std::size_t> kept = extract_cell_planes(scan.cloud, ours, rng).cell_inlier_indices();
  std::set<std::size_t> expected = scan.thesis_keeps;
  expected.insert(scan.second_plane.begin(), scan.second_plane.end());
  EXPECT_EQ(std::set<std::size_t>(kept.begin(), kept.end()), expected);

  PlaneExtractionSettings at_ten = thesis_at_layer_1();
  at_ten.min_inliers = 10;  // "at least 10" instead of "exceeds 10": the plane x = 5 is kept
  Rng again(7);
  EXPECT_EQ(extract_cell_planes(scan.cloud, at_ten, again).cell_inlier_indices().size(),
            scan.thesis_keeps.size() + 10);
}

TEST(ThesisFeatureSampling, TheSamplerAndItsPresetReadFromYaml) {
  const KnownScan scan = known_scan();
  const auto sampler = make_sampler("fbs", YAML::Load("{preset: thesis, split_layer: 1}"), "t.yaml");
  Rng rng(7);
  const std::vector<std::size_t> kept = sampler->select(scan.cloud, rng);
  EXPECT_EQ(std::set<std::size_t>(kept.begin(), kept.end()), scan.thesis_keeps);
  EXPECT_THROW(make_sampler("fbs", YAML::Load("{preset: thesys}"), "t.yaml"), InputError);
  EXPECT_THROW(make_sampler("fbs", YAML::Load("{split_layer: 9}"), "t.yaml"), InputError);
}

TEST(ThesisFeatureSampling, SplitLayerFourOfACampusSizedBox) {
  // A 64 × 64 × 4 m box at layer 4 of q = 8: edge (16384 / 4096)^(1/3) = 1.587 m.
  PointCloud cloud;
  cloud.push_back(Eigen::Vector3f(-32, -32, 0));
  cloud.push_back(Eigen::Vector3f(32, 32, 4));
  Rng rng(1);
  EXPECT_NEAR(extract_cell_planes(cloud, thesis_feature_sampling(), rng).stats.cell_edge, std::cbrt(4.0),
              1e-9);
}

TEST(ThesisFbmlndt, RecoversATwoMetreMotionFromAZeroGuessOnTheFeatureSampleAlone) {
  const test::Scene scene = test::courtyard();
  const Eigen::Isometry3d reference_pose = test::sensor_pose(0, 0, 1.5, 0),
                          input_pose = test::sensor_pose(2.0, 0.0, 1.5, 0.0);
  Rng rng(21);
  const PointCloud reference = test::sample_scene(scene, reference_pose, rng, 6.0, 2.0, 200);
  const PointCloud input = test::sample_scene(scene, input_pose, rng, 6.0, 2.0, 200);
  const Eigen::Isometry3d truth = reference_pose.inverse() * input_pose;  // p_ref = truth · p_input

  const char* settings = "{preset: thesis, fallback: none, seed: 5, features: {preset: thesis}}";
  auto matcher = make_matcher("fbmlndt", YAML::Load(settings), "t.yaml");
  matcher->set_reference(reference);
  const RegistrationResult r = matcher->align(input, Eigen::Isometry3d::Identity());
  const Eigen::Isometry3d error = truth.inverse() * r.T;
  std::printf("thesis fbmlndt: %s; %zu of %zu input points; error %.3f m, %.3f deg\n", r.summary().c_str(),
              r.input_points, input.size(), translation_norm(error), rotation_angle(error) * 180.0 / M_PI);
  // The matched points are the thesis' feature sample, no GBS points added.
  Rng ransac(5);
  EXPECT_EQ(r.input_points,
            extract_cell_planes(input, thesis_feature_sampling(), ransac).cell_inlier_indices().size());
  EXPECT_TRUE(r.fallback.empty()) << r.fallback;
  // "A few cm" (§5.1.2.1): the thesis preset's plain sum and Newton step end 6 cm off here.
  EXPECT_LT(translation_norm(error), 0.10);
  EXPECT_LT(rotation_angle(error) * 180.0 / M_PI, 0.5);
}

}  // namespace
}  // namespace sextant
