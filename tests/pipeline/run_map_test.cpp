// The run's map (pipeline/run_map.hpp): scans placed by known poses give the voxel centroids computed
// by hand; a world point seen by many scans is one map point; the size is the number of occupied
// voxels however many scans are added; the default voxel follows the data's scale.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <tuple>
#include <vector>

#include "sextant/core/error.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/pipeline/run_map.hpp"

namespace sextant {
namespace {

Eigen::Isometry3d translation(double x, double y, double z) {
  return Eigen::Isometry3d(Eigen::Translation3d(x, y, z));
}

TEST(RunMap, ScansPlacedByKnownPosesGiveTheCentroidsComputedByHand) {
  RunMap map(1.0);
  PointCloud a;  // at the identity
  a.push_back({0.2f, 0.2f, 0.2f}, 10.0f);
  a.push_back({1.5f, 0.5f, 0.5f}, 20.0f);  // voxel (1, 0, 0)
  a.push_back({0.6f, 0.4f, 0.2f}, 30.0f);  // voxel (0, 0, 0) again
  map.add(a, Eigen::Isometry3d::Identity());
  PointCloud b;  // one metre along x: (0.1, 0.1, 0.1) is (1.1, 0.1, 0.1) in the world
  b.push_back({0.1f, 0.1f, 0.1f}, 40.0f);
  b.push_back({-1.25f, 2.5f, 0.5f}, 50.0f);  // (−0.25, 2.5, 0.5): voxel (−1, 2, 0), not (0, 2, 0)
  map.add(b, translation(1.0, 0.0, 0.0));
  // A quarter turn about z and (0, 0, 3): (x, y, z) ↦ (−y, x, z + 3).
  PointCloud c;
  c.push_back({0.5f, -1.7f, -2.5f}, 60.0f);  // (1.7, 0.5, 0.5): voxel (1, 0, 0)
  Eigen::Isometry3d turn = translation(0.0, 0.0, 3.0);
  turn.rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  map.add(c, turn);

  ASSERT_EQ(map.size(), 3u);
  EXPECT_EQ(map.scans(), 3u);
  EXPECT_EQ(map.points_added(), 6u);
  const PointCloud cloud = map.cloud();
  ASSERT_EQ(cloud.size(), 3u);
  ASSERT_TRUE(cloud.has_intensity());
  // In the order the voxels were first hit.
  EXPECT_TRUE(cloud[0].isApprox(Eigen::Vector3f(0.4f, 0.3f, 0.2f), 1e-6f)) << cloud[0].transpose();
  EXPECT_FLOAT_EQ(cloud.intensity()[0], 20.0f);  // (10 + 30) / 2
  EXPECT_TRUE(cloud[1].isApprox(
      Eigen::Vector3f((1.5f + 1.1f + 1.7f) / 3, (0.5f + 0.1f + 0.5f) / 3, (0.5f + 0.1f + 0.5f) / 3), 1e-6f))
      << cloud[1].transpose();
  EXPECT_FLOAT_EQ(cloud.intensity()[1], 40.0f);  // (20 + 40 + 60) / 3
  EXPECT_TRUE(cloud[2].isApprox(Eigen::Vector3f(-0.25f, 2.5f, 0.5f), 1e-6f)) << cloud[2].transpose();
  EXPECT_FLOAT_EQ(cloud.intensity()[2], 50.0f);
}

TEST(RunMap, AWorldPointSeenByManyScansIsOneMapPoint) {
  const Eigen::Vector3d world(12.25, -3.75, 1.25);  // the middle of a 0.5 m voxel
  RunMap map(0.5);
  Rng rng(7);
  for (int k = 0; k < 200; ++k) {
    Eigen::Isometry3d pose = translation(rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-2, 2));
    pose.rotate(Eigen::AngleAxisd(rng.uniform(-M_PI, M_PI), Eigen::Vector3d::UnitZ()));
    PointCloud scan;
    scan.push_back((pose.inverse() * world).cast<float>());  // the point as that scan sees it
    map.add(scan, pose);
  }
  ASSERT_EQ(map.size(), 1u);
  EXPECT_LT((map.cloud()[0].cast<double>() - world).norm(), 1e-4);
  EXPECT_FALSE(map.cloud().has_intensity());
}

TEST(RunMap, ItsSizeIsTheOccupiedVoxelsHoweverManyScansAreAdded) {
  Rng rng(3);
  PointCloud scan;
  for (int i = 0; i < 2000; ++i)
    scan.push_back(Eigen::Vector3f(static_cast<float>(rng.uniform(-10, 10)),
                                   static_cast<float>(rng.uniform(-10, 10)),
                                   static_cast<float>(rng.uniform(0, 3))));
  const double voxel = 0.7, inverse = 1.0 / voxel;
  RunMap map(voxel);
  std::set<std::tuple<long, long, long>> occupied;  // counted here with the formula, not the class
  for (int k = 0; k < 300; ++k) {
    const Eigen::Isometry3d pose = translation(0.35 * (k % 4), 0.0, 0.0);  // four places, again and again
    map.add(scan, pose);
    for (const Eigen::Vector3f& p : scan.points()) {
      const Eigen::Vector3d w = pose * p.cast<double>();
      occupied.emplace(std::lround(std::floor(w.x() * inverse)), std::lround(std::floor(w.y() * inverse)),
                       std::lround(std::floor(w.z() * inverse)));
    }
    ASSERT_EQ(map.size(), occupied.size()) << "after " << k + 1 << " scans";
  }
  EXPECT_EQ(map.scans(), 300u);
  EXPECT_EQ(map.points_added(), 300u * 2000u);
  EXPECT_LT(map.size(), 4u * 2000u);  // never more than the four placings' points
  EXPECT_EQ(map.cloud().size(), map.size());
}

TEST(RunMap, IntensityIsKeptOnlyWhileEveryScanHasIt) {
  RunMap map(1.0);
  PointCloud with;
  with.push_back({0.5f, 0.5f, 0.5f}, 1.0f);
  map.add(with, Eigen::Isometry3d::Identity());
  EXPECT_TRUE(map.has_intensity());
  PointCloud without;
  without.push_back({3.5f, 0.5f, 0.5f});
  map.add(without, Eigen::Isometry3d::Identity());
  EXPECT_FALSE(map.has_intensity());
  EXPECT_FALSE(map.cloud().has_intensity());
  EXPECT_EQ(map.cloud().size(), 2u);
}

TEST(RunMap, PointsBeyondTheVoxelIndexAreCountedNotAdded) {
  RunMap map(0.001);
  PointCloud scan;
  scan.push_back({1.0f, 2.0f, 3.0f});
  scan.push_back({1e7f, 0.0f, 0.0f});  // 10¹⁰ voxels out: past a 32-bit index
  map.add(scan, Eigen::Isometry3d::Identity());
  EXPECT_EQ(map.size(), 1u);
  EXPECT_EQ(map.points_added(), 1u);
  EXPECT_EQ(map.skipped_points(), 1u);
}

TEST(RunMap, ABadVoxelIsRefused) {
  for (const double bad : {0.0, -0.1, std::numeric_limits<double>::infinity(), std::nan("")}) {
    EXPECT_THROW(RunMap{bad}, InputError) << bad;
    EXPECT_FALSE(map_voxel_problem(bad).empty()) << bad;
  }
  EXPECT_TRUE(map_voxel_problem(0.05).empty());
  EXPECT_EQ(RunMap(0.05).voxel_size(), 0.05);
  EXPECT_EQ(RunMap(0.05).cloud().size(), 0u);
}

/// `n` points on a circle of radius `r` about `centre` (in the plane z = centre.z).
PointCloud ring(double r, std::size_t n, const Eigen::Vector3d& centre = Eigen::Vector3d::Zero()) {
  PointCloud cloud;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    cloud.push_back((centre + r * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0)).cast<float>());
  }
  return cloud;
}

TEST(RunMap, TheDefaultVoxelIsAHundredthOfTheMedianRangeRounded) {
  // Three quarters of the points at 14.3 m, a quarter at 80 m: the median is 14.3 m.
  PointCloud scan = ring(14.3, 300);
  for (const Eigen::Vector3f& p : ring(80.0, 100).points()) scan.push_back(p);
  EXPECT_NEAR(scan_median_range(scan), 14.3, 1e-4);
  EXPECT_DOUBLE_EQ(default_map_voxel_size(scan), 0.2);  // 0.143: nearer 0.2 than 0.1 on a log scale
  EXPECT_DOUBLE_EQ(default_map_voxel_size(ring(3.0, 50)), 0.02);
  EXPECT_DOUBLE_EQ(default_map_voxel_size(ring(4.0, 50)), 0.05);
  EXPECT_DOUBLE_EQ(default_map_voxel_size(ring(100.0, 50)), 1.0);
  EXPECT_DOUBLE_EQ(default_map_voxel_size(ring(800.0, 50)), 10.0);
  EXPECT_DOUBLE_EQ(default_map_voxel_size(ring(0.5, 50)), 0.01);  // the floor
  EXPECT_DOUBLE_EQ(default_map_voxel_size(PointCloud{}), 0.01);
  // A scan exported in a map frame, far from its origin: the range from where it is registered about.
  const PointCloud far = ring(20.0, 60, Eigen::Vector3d(5000.0, -3000.0, 10.0));
  EXPECT_NEAR(scan_median_range(far), 20.0, 1e-2);
  EXPECT_DOUBLE_EQ(default_map_voxel_size(far), 0.2);
}

}  // namespace
}  // namespace sextant
