// Scan Context: the yaw it recovers, what it tells apart, and the revisits it proposes.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sextant/core/rng.hpp"
#include "sextant/posegraph/scan_context.hpp"
#include "square_drive.hpp"

namespace sextant {
namespace {

/// A street of random boxes (walls sampled every 0.3 m, 1–12 m tall) on a flat ground, in the world.
std::vector<Eigen::Vector3d> random_place(std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Eigen::Vector3d> world;
  for (int b = 0; b < 25; ++b) {
    const double cx = rng.uniform(-60, 60), cy = rng.uniform(-60, 60);
    const double hx = rng.uniform(1, 6), hy = rng.uniform(1, 6), height = rng.uniform(1, 12);
    for (double z = 0.0; z < height; z += 0.3)
      for (double t = -1.0; t <= 1.0; t += 0.3 / std::max(hx, hy)) {
        world.emplace_back(cx + t * hx, cy - hy, z);
        world.emplace_back(cx + t * hx, cy + hy, z);
        world.emplace_back(cx - hx, cy + t * hy, z);
        world.emplace_back(cx + hx, cy + t * hy, z);
      }
  }
  for (double x = -70; x < 70; x += 1.0)
    for (double y = -70; y < 70; y += 1.0) world.emplace_back(x, y, 0.0);
  return world;
}

/// The world seen from a sensor at `sensor` (world ← sensor), 1.8 m above the ground.
PointCloud scan_from(const std::vector<Eigen::Vector3d>& world, const Eigen::Isometry3d& sensor) {
  const Eigen::Isometry3d to_sensor = (sensor * Eigen::Translation3d(0, 0, 1.8)).inverse();
  PointCloud cloud;
  for (const Eigen::Vector3d& p : world) cloud.mutable_points().push_back((to_sensor * p).cast<float>());
  return cloud;
}

TEST(ScanContext, BinsHoldTheHighestPointAndTheRingKeyTheirMean) {
  PointCloud cloud;
  cloud.mutable_points() = {{1, 0, 0}, {1.5, 0.1, 0.5}, {0, 1, 0}, {-1, 0, -3}, {10, 0, 1}};
  ScanContextSettings s;
  s.rings = 2;
  s.sectors = 4;
  s.max_range = 20.0;
  const ScanContext sc = make_scan_context(cloud, s);
  EXPECT_FLOAT_EQ(sc.image(0, 0), 2.5f);  // the higher of two points, z + 2
  EXPECT_FLOAT_EQ(sc.image(0, 1), 2.0f);
  EXPECT_FLOAT_EQ(sc.image(0, 2), 0.0f);  // the point 3 m down is left out
  EXPECT_FLOAT_EQ(sc.image(1, 0), 3.0f);
  EXPECT_FLOAT_EQ(sc.ring_key(0), 1.125f);  // (2.5 + 2 + 0 + 0) / 4
  EXPECT_FLOAT_EQ(sc.ring_key(1), 0.75f);
}

TEST(ScanContext, RecoversTheYawBetweenTwoViewsOfOnePlace) {
  const auto world = random_place(7);
  const ScanContextSettings s;
  const double sector = 2.0 * M_PI / static_cast<double>(s.sectors);
  for (const double yaw_deg : {0.0, 37.0, 90.0, 170.0, -65.0, -178.0}) {
    const double yaw = yaw_deg * M_PI / 180.0;
    const ScanContext a = make_scan_context(scan_from(world, test::planar_pose(3, -2, 0.3)), s);
    const ScanContext b = make_scan_context(scan_from(world, test::planar_pose(3.4, -2.2, 0.3 + yaw)), s);
    const ScanContextMatch m = compare_scan_contexts(a, b);
    // A yaw between two sector borders moves every wall across bins: up to 0.2 here, against ≈ 0.5
    // between different places (next test).
    EXPECT_LT(m.distance, s.max_distance) << yaw_deg;
    EXPECT_LE(std::abs(std::remainder(m.yaw - yaw, 2.0 * M_PI)), sector) << yaw_deg << "° gave " << m.yaw;
  }
}

TEST(ScanContext, TellsDifferentPlacesApart) {
  const ScanContextSettings s;
  const ScanContext here = make_scan_context(scan_from(random_place(7), test::planar_pose(0, 0, 0)), s);
  const ScanContext again = make_scan_context(scan_from(random_place(7), test::planar_pose(1, 0.5, 2.0)), s);
  const double same = compare_scan_contexts(here, again).distance;
  for (std::uint64_t seed = 20; seed < 25; ++seed) {
    const ScanContext there = make_scan_context(scan_from(random_place(seed), test::planar_pose(0, 0, 0)), s);
    EXPECT_GT(compare_scan_contexts(here, there).distance, 3.0 * same) << "place " << seed;
    EXPECT_GT(compare_scan_contexts(here, there).distance, s.max_distance) << "place " << seed;
  }
}

TEST(ScanContext, NoCommonColumnIsTheLargestDistance) {
  const ScanContextSettings s;
  const ScanContext empty = make_scan_context(PointCloud{}, s);
  const ScanContext full = make_scan_context(scan_from(random_place(3), test::planar_pose(0, 0, 0)), s);
  EXPECT_DOUBLE_EQ(compare_scan_contexts(empty, full).distance, 1.0);
}

TEST(ScanContext, ProposesTheRevisitAndNothingElse) {
  // 60 scans along distinct places; scan 50 comes back to scan 5's place, turned by 120°.
  ScanContextSettings s;
  s.min_index_gap = 20;
  std::vector<ScanContext> contexts;
  for (std::uint64_t k = 0; k < 60; ++k) {
    const bool revisit = k == 50;
    contexts.push_back(
        make_scan_context(scan_from(random_place(revisit ? 100 + 5 : 100 + k),
                                    revisit ? test::planar_pose(0.8, -0.6, 2.1) : test::planar_pose(0, 0, 0)),
                          s));
  }
  const std::vector<PlaceMatch> found = find_place_matches(contexts, s);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].i, 5u);
  EXPECT_EQ(found[0].j, 50u);
  EXPECT_NEAR(std::remainder(found[0].match.yaw - 2.1, 2.0 * M_PI), 0.0, 2.0 * M_PI / 60.0);
  const Eigen::Isometry3d guess = found[0].guess();
  EXPECT_NEAR(Eigen::AngleAxisd(guess.linear()).angle(), std::abs(found[0].match.yaw), 1e-9);
  EXPECT_EQ(guess.translation().norm(), 0.0);
}

TEST(ScanContext, SettingsAreChecked) {
  std::string why;
  EXPECT_TRUE(ScanContextSettings{}.valid(&why));
  ScanContextSettings s;
  s.sectors = 2;
  EXPECT_FALSE(s.valid(&why));
  s = {};
  s.max_distance = 1.5;
  EXPECT_FALSE(s.valid(&why));
  EXPECT_NE(why.find("max_distance"), std::string::npos);
}

}  // namespace
}  // namespace sextant
