#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <sstream>

#include "sextant/core/io/kitti.hpp"
#include "sextant/core/pose.hpp"
#include "test_util.hpp"

namespace sextant {
namespace {

using test::data_dir;
using test::expect_input_error;
using test::TempDir;
using test::write_text;

// Independent of the library's parser: istream reading of n numbers after an optional label.
std::vector<double> numbers_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<double> v;
  std::string token;
  while (in >> token) {
    if (token.back() == ':') continue;
    v.push_back(std::stod(token));
  }
  return v;
}

Eigen::Matrix4d matrix_3x4(const std::vector<double>& v) {
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) M(r, c) = v[4 * r + c];
  return M;
}

TEST(KittiPair, RelativePoseEqualsTrInvP0InvP1Tr) {
  const auto dir = data_dir() / "kitti00_pair";
  std::ifstream poses_in(dir / "kitti00_poses_cam0_frames0-1.txt");
  std::ifstream calib_in(dir / "kitti00_calib_Tr_velo_to_cam0.txt");
  std::string l0, l1, tr;
  std::getline(poses_in, l0);
  std::getline(poses_in, l1);
  std::getline(calib_in, tr);
  const Eigen::Matrix4d P0 = matrix_3x4(numbers_of(l0)), P1 = matrix_3x4(numbers_of(l1));
  const Eigen::Matrix4d Tr = matrix_3x4(numbers_of(tr));
  const Eigen::Matrix4d expected = Tr.inverse() * P0.inverse() * P1 * Tr;

  const auto camera = read_kitti_poses(dir / "kitti00_poses_cam0_frames0-1.txt");
  ASSERT_EQ(camera.size(), 2u);
  const auto velo =
      kitti_velodyne_poses(camera, read_kitti_calib_tr(dir / "kitti00_calib_Tr_velo_to_cam0.txt"));
  ASSERT_EQ(velo.size(), 2u);
  EXPECT_TRUE(velo[0].isApprox(Eigen::Isometry3d::Identity(), 1e-12));
  EXPECT_TRUE(velo[1].matrix().isApprox(expected, 1e-12));

  // The shared derived file (printed with 9 significant digits): the same arithmetic. It is not ground
  // truth for the scans (data/README.md, correction); only the format and the composition are checked.
  std::ifstream derived_in(dir / "T_velo0_from_velo1_DERIVED.txt");
  Eigen::Matrix4d derived;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) derived_in >> derived(r, c);
  EXPECT_LT((velo[1].matrix() - derived).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(KittiScan, SharedXyz32Counts) {
  ScanLoadReport report;
  const PointCloud a = read_xyz32(data_dir() / "kitti00_pair" / "000000.xyz32.bin", &report);
  EXPECT_EQ(report.points_read, 124668u);
  EXPECT_EQ(a.size() + report.non_finite_dropped, 124668u);
  const PointCloud b = read_xyz32(data_dir() / "kitti00_pair" / "000001.xyz32.bin");
  EXPECT_EQ(b.size(), 124605u);
  EXPECT_FALSE(a.has_intensity());
}

TEST(KittiScan, RoundTripsBinAndXyz32) {
  TempDir dir;
  PointCloud cloud;
  cloud.push_back({1.0f, -2.0f, 3.5f}, 0.25f);
  cloud.push_back({-7.0f, 0.5f, 0.0f}, 0.75f);
  write_kitti_velodyne(dir / "a.bin", cloud);
  EXPECT_EQ(std::filesystem::file_size(dir / "a.bin"), 32u);
  const PointCloud bin = read_kitti_velodyne(dir / "a.bin");
  ASSERT_EQ(bin.size(), 2u);
  EXPECT_EQ(bin.points(), cloud.points());
  EXPECT_EQ(bin.intensity(), cloud.intensity());

  write_xyz32(dir / "a.xyz32.bin", cloud);
  EXPECT_EQ(std::filesystem::file_size(dir / "a.xyz32.bin"), 24u);
  EXPECT_EQ(read_xyz32(dir / "a.xyz32.bin").points(), cloud.points());
}

TEST(KittiScan, TruncatedBinNamesByteOffset) {
  TempDir dir;
  write_text(dir / "t.bin", std::string(16 * 2 + 5, '\0'));
  expect_input_error([&] { read_kitti_velodyne(dir / "t.bin"); }, dir / "t.bin", "byte 32",
                     "not a multiple of the 16");
  // A 12-byte-per-point file read as 16-byte points gets a hint.
  write_text(dir / "x.bin", std::string(12 * 3, '\0'));
  expect_input_error([&] { read_kitti_velodyne(dir / "x.bin"); }, dir / "x.bin", "byte 32", ".xyz32.bin");
}

TEST(KittiScan, NonFiniteDroppedAndCounted) {
  TempDir dir;
  PointCloud cloud;
  cloud.push_back({1.0f, 2.0f, 3.0f}, 1.0f);
  cloud.push_back({std::numeric_limits<float>::quiet_NaN(), 2.0f, 3.0f}, 1.0f);
  cloud.push_back({1.0f, std::numeric_limits<float>::infinity(), 3.0f}, 1.0f);
  write_kitti_velodyne(dir / "n.bin", cloud);
  ScanLoadReport report;
  EXPECT_EQ(read_kitti_velodyne(dir / "n.bin", &report).size(), 1u);
  EXPECT_EQ(report.points_read, 3u);
  EXPECT_EQ(report.non_finite_dropped, 2u);
}

TEST(KittiPoses, RoundTripAndBadInput) {
  TempDir dir;
  const std::vector<Eigen::Isometry3d> poses = {to_isometry({1, 2, 3, 0.1, 0.2, 0.3}),
                                                to_isometry({-4, 5, -6, -0.3, 0.0, 3.0})};
  write_kitti_poses(dir / "p.txt", poses);
  const auto back = read_kitti_poses(dir / "p.txt");
  ASSERT_EQ(back.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) EXPECT_TRUE(back[i].isApprox(poses[i], 1e-7));

  write_text(dir / "bad.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1\n");
  expect_input_error([&] { read_kitti_poses(dir / "bad.txt"); }, dir / "bad.txt", "line 2", "found 11");
  write_text(dir / "calib.txt", "P0: 1 2 3\n");
  expect_input_error([&] { read_kitti_calib_tr(dir / "calib.txt"); }, dir / "calib.txt", "", "no 'Tr:' line");
  write_text(dir / "times.txt", "0.0\n0.1\nzero\n");
  expect_input_error([&] { read_kitti_times(dir / "times.txt"); }, dir / "times.txt", "line 3", "'zero'");
}

}  // namespace
}  // namespace sextant
