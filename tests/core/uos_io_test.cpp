#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "sextant/core/io/uos.hpp"
#include "sextant/core/pose.hpp"
#include "test_util.hpp"

namespace sextant {
namespace {

using test::data_dir;
using test::expect_input_error;
using test::TempDir;
using test::threedtk_euler_to_matrix4;
using test::write_text;

TEST(UosFrame, PointConversionAxesAndUnits) {
  // x_int = z_uos/100, y_int = −x_uos/100, z_int = y_uos/100.
  const Eigen::Vector3d p = uos_to_internal({100.0, 200.0, 300.0});
  EXPECT_NEAR(p.x(), 3.0, 1e-12);
  EXPECT_NEAR(p.y(), -1.0, 1e-12);
  EXPECT_NEAR(p.z(), 2.0, 1e-12);
  EXPECT_TRUE(internal_to_uos(p).isApprox(Eigen::Vector3d(100.0, 200.0, 300.0)));
}

TEST(UosFrame, PoseConversionCommutesWithPointMapping) {
  // T_int · uos_to_internal(p) == uos_to_internal(M · p) for every point p.
  const Eigen::Matrix4d M = threedtk_euler_to_matrix4({12.0, -30.0, 250.0}, {0.1, -0.7, 0.3});
  const Eigen::Isometry3d T = uos_pose_to_internal(M);
  EXPECT_NEAR(T.linear().determinant(), 1.0, 1e-12);
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(-40, 5, 700)}) {
    const Eigen::Vector3d mapped_uos = (M * p.homogeneous()).head<3>();
    EXPECT_TRUE((T * uos_to_internal(p)).isApprox(uos_to_internal(mapped_uos), 1e-12));
  }
  EXPECT_TRUE(internal_pose_to_uos(T).isApprox(M, 1e-12));
}

TEST(UosFrame, EulerToMatrixMatches3DTK) {
  const Eigen::Vector3d t(1.5, -2.0, 30.0), r(0.3, -0.4, 1.2);
  EXPECT_TRUE(uos_euler_to_matrix(t, r).isApprox(threedtk_euler_to_matrix4(t, r), 1e-14));
}

TEST(UosScan, SharedScansGiveDocumentedCounts) {
  // data/README.md: 81,360 point lines each after the "360 x 225" header; the "no return"
  // points (range ≥ 3275 cm) are dropped and counted.
  const struct {
    const char* name;
    std::size_t no_return;
  } expected[] = {{"scan000.3d", 1481}, {"scan001.3d", 1313}, {"scan002.3d", 1618}};
  for (const auto& e : expected) {
    ScanLoadReport report;
    const PointCloud cloud = read_uos_scan(data_dir() / "uos_3dtk" / e.name, &report);
    EXPECT_EQ(report.points_read, 81360u) << e.name;
    EXPECT_EQ(report.header_lines_skipped, 1u) << e.name;
    EXPECT_EQ(report.no_return_dropped, e.no_return) << e.name;
    EXPECT_EQ(report.non_finite_dropped, 0u) << e.name;
    EXPECT_EQ(cloud.size(), 81360u - e.no_return) << e.name;
    // Indoor scan in metres: everything within the 32.76 m range.
    const Bounds b = cloud.bounds();
    EXPECT_LT(b.extent().maxCoeff(), 2 * 32.76f);
    EXPECT_GT(b.extent().minCoeff(), 1.0f);
  }
}

TEST(UosScan, FirstPointConverted) {
  // First point line of scan000.3d: "10.1 0 0" → (0, −0.101, 0) m.
  const PointCloud cloud = read_uos_scan(data_dir() / "uos_3dtk" / "scan000.3d");
  EXPECT_NEAR(cloud[0].x(), 0.0f, 1e-7f);
  EXPECT_NEAR(cloud[0].y(), -0.101f, 1e-7f);
  EXPECT_NEAR(cloud[0].z(), 0.0f, 1e-7f);
}

TEST(UosPose, SharedPoseFile) {
  // scan001.pose: "-3.10605 -7.50803 156.917" cm, "1.35694 -0.852409 -0.56224" deg.
  const Eigen::Isometry3d T = read_uos_pose(data_dir() / "uos_3dtk" / "scan001.pose");
  EXPECT_NEAR(T.translation().x(), 1.56917, 1e-9);
  EXPECT_NEAR(T.translation().y(), 0.0310605, 1e-9);
  EXPECT_NEAR(T.translation().z(), -0.0750803, 1e-9);
  const Eigen::Vector3d deg(1.35694, -0.852409, -0.56224);
  const Eigen::Matrix4d M = threedtk_euler_to_matrix4({-3.10605, -7.50803, 156.917}, deg * M_PI / 180.0);
  EXPECT_TRUE(internal_pose_to_uos(T).isApprox(M, 1e-12));
}

TEST(UosFrames, LastLineIsFinalRegistration) {
  const auto frames = read_uos_frames(data_dir() / "uos_3dtk" / "scan001.frames");
  ASSERT_EQ(frames.size(), 3u);
  // Last line translation (uos cm): -3.6331 -9.08315 156.796 → internal m.
  EXPECT_TRUE(frames.back().translation().isApprox(Eigen::Vector3d(1.56796, 0.036331, -0.0908315), 1e-9));
  EXPECT_NEAR(frames.back().linear().determinant(), 1.0, 1e-5);
}

// Median nearest-neighbour distance from (every 50th point of) `moving` to `fixed`, with a
// voxel hash of cell `cell` searched over the 27 neighbouring cells (capped at `cell`).
double median_nn_distance(const PointCloud& fixed, const PointCloud& moving, float cell) {
  auto key = [cell](const Eigen::Vector3f& p) {
    const auto k = (p / cell).array().floor().cast<long long>();
    return (k[0] * 73856093LL) ^ (k[1] * 19349663LL) ^ (k[2] * 83492791LL);
  };
  std::unordered_multimap<long long, Eigen::Vector3f> grid;
  for (const auto& p : fixed.points()) grid.emplace(key(p), p);
  std::vector<float> distances;
  for (std::size_t i = 0; i < moving.size(); i += 50) {
    const Eigen::Vector3f& q = moving[i];
    if (q.norm() < 0.6f) continue;  // robot self-hits coincide in every scan
    float best = cell;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto range = grid.equal_range(key(q + Eigen::Vector3f(dx, dy, dz) * cell));
          for (auto it = range.first; it != range.second; ++it)
            best = std::min(best, (it->second - q).norm());
        }
    distances.push_back(best);
  }
  std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
  return distances[distances.size() / 2];
}

TEST(UosFrames, Scan001OverlaysScan000BetterThanIdentity) {
  const auto dir = data_dir() / "uos_3dtk";
  const PointCloud scan0 = read_uos_scan(dir / "scan000.3d");
  const PointCloud scan1 = read_uos_scan(dir / "scan001.3d");
  const Eigen::Isometry3d T0 = read_uos_frames(dir / "scan000.frames").back();
  const Eigen::Isometry3d T1 = read_uos_frames(dir / "scan001.frames").back();
  const double identity = median_nn_distance(scan0, scan1, 0.5f);
  const double registered = median_nn_distance(scan0, scan1.transformed(relative(T0, T1)), 0.5f);
  EXPECT_LT(registered, 0.5 * identity) << "identity " << identity << " m, registered " << registered << " m";
}

TEST(UosRoundTrip, ScanPoseFrames) {
  TempDir dir;
  PointCloud cloud;
  cloud.push_back({1.0f, -2.5f, 0.25f});
  cloud.push_back({-3.0f, 0.125f, 7.0f});
  write_uos_scan(dir / "a.3d", cloud);
  const PointCloud back = read_uos_scan(dir / "a.3d");
  ASSERT_EQ(back.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) EXPECT_TRUE(back[i].isApprox(cloud[i], 1e-6f));

  const Eigen::Isometry3d T = to_isometry({1.0, -2.0, 0.5, 0.1, -0.2, 2.5});
  write_uos_pose(dir / "a.pose", T);
  EXPECT_TRUE(read_uos_pose(dir / "a.pose").isApprox(T, 1e-7));

  const std::vector<Eigen::Isometry3d> frames = {Eigen::Isometry3d::Identity(), T};
  write_uos_frames(dir / "a.frames", frames);
  const auto frames_back = read_uos_frames(dir / "a.frames");
  ASSERT_EQ(frames_back.size(), 2u);
  EXPECT_TRUE(frames_back[1].isApprox(T, 1e-7));
}

TEST(UosRoundTrip, IntensityColumn) {
  TempDir dir;
  PointCloud cloud;
  cloud.push_back({1.0f, 2.0f, 3.0f}, 0.5f);
  write_uos_scan(dir / "i.3d", cloud);
  const PointCloud back = read_uos_scan(dir / "i.3d");
  ASSERT_TRUE(back.has_intensity());
  EXPECT_FLOAT_EQ(back.intensity()[0], 0.5f);
}

TEST(UosBadInput, MalformedNumberNamesLine) {
  TempDir dir;
  write_text(dir / "bad.3d", "360 x 225\n1 2 3\n4 5 6\n7 abc 9\n");
  expect_input_error([&] { read_uos_scan(dir / "bad.3d"); }, dir / "bad.3d", "line 4", "'abc'");
}

TEST(UosBadInput, TooFewNumbers) {
  TempDir dir;
  write_text(dir / "short.3d", "1 2 3\n4 5\n");
  expect_input_error([&] { read_uos_scan(dir / "short.3d"); }, dir / "short.3d", "line 2", "found 2");
}

TEST(UosBadInput, NonFinitePointsDroppedAndCounted) {
  TempDir dir;
  write_text(dir / "nan.3d", "1 2 3\nnan 1 1\n4 inf 6\n0 3276 0\n7 8 9\n");
  ScanLoadReport report;
  const PointCloud cloud = read_uos_scan(dir / "nan.3d", &report);
  EXPECT_EQ(cloud.size(), 2u);
  EXPECT_EQ(report.points_read, 5u);
  EXPECT_EQ(report.non_finite_dropped, 2u);
  EXPECT_EQ(report.no_return_dropped, 1u);
}

TEST(UosBadInput, MissingAndMalformedPoseFiles) {
  TempDir dir;
  expect_input_error([&] { read_uos_pose(dir / "none.pose"); }, dir / "none.pose", "", "cannot open");
  write_text(dir / "one.pose", "1 2 3\n");
  expect_input_error([&] { read_uos_pose(dir / "one.pose"); }, dir / "one.pose", "", "expected 2 lines");
  write_text(dir / "bad.pose", "1 2 3\n0 x 0\n");
  expect_input_error([&] { read_uos_pose(dir / "bad.pose"); }, dir / "bad.pose", "line 2", "'x'");
  write_text(dir / "bad.frames", "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 2\n1 0 0\n");
  expect_input_error([&] { read_uos_frames(dir / "bad.frames"); }, dir / "bad.frames", "line 2", "found 3");
  write_text(dir / "empty.frames", "");
  expect_input_error([&] { read_uos_frames(dir / "empty.frames"); }, dir / "empty.frames", "", "no frames");
}

}  // namespace
}  // namespace sextant
