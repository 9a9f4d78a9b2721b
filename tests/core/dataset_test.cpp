#include <gtest/gtest.h>

#include "sextant/core/dataset.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/io/kitti.hpp"
#include "sextant/core/io/uos.hpp"
#include "sextant/core/pose.hpp"
#include "test_util.hpp"

namespace sextant {
namespace {

using test::data_dir;
using test::expect_input_error;
using test::TempDir;
using test::write_text;

TEST(UosDataset, SharedFolder) {
  const auto ds = open_dataset(data_dir() / "uos_3dtk");
  EXPECT_EQ(ds->metadata().format, "uos");
  EXPECT_EQ(ds->metadata().name, "uos_3dtk");
  ASSERT_EQ(ds->size(), 3u);
  EXPECT_TRUE(ds->metadata().has_odometry);
  EXPECT_TRUE(ds->metadata().has_ground_truth);
  EXPECT_TRUE(ds->odometry(0)->isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_TRUE(
      ds->ground_truth(2)->isApprox(read_uos_frames(data_dir() / "uos_3dtk" / "scan002.frames").back()));
  EXPECT_TRUE(ds->odometry(1)->isApprox(read_uos_pose(data_dir() / "uos_3dtk" / "scan001.pose")));
  ScanLoadReport report;
  EXPECT_EQ(ds->scan(1, &report).size(), 80047u);
  EXPECT_EQ(report.no_return_dropped, 1313u);
  EXPECT_THROW(ds->odometry(3), std::out_of_range);
}

TEST(UosDataset, SortedByNumberAndOptionalPoses) {
  TempDir dir;
  PointCloud cloud;
  cloud.push_back({1, 2, 3});
  write_uos_scan(dir / "scan010.3d", cloud);
  cloud.push_back({4, 5, 6});
  write_uos_scan(dir / "scan002.3d", cloud);
  const auto ds = open_dataset(dir.path());
  ASSERT_EQ(ds->size(), 2u);
  EXPECT_EQ(ds->scan_file(0).filename(), "scan002.3d");
  EXPECT_EQ(ds->scan(0).size(), 2u);
  EXPECT_FALSE(ds->metadata().has_odometry);
  EXPECT_FALSE(ds->odometry(0).has_value());
  EXPECT_FALSE(ds->ground_truth(1).has_value());
}

TEST(UosDataset, MissingPoseFileNamed) {
  TempDir dir;
  PointCloud cloud;
  cloud.push_back({1, 2, 3});
  write_uos_scan(dir / "scan000.3d", cloud);
  write_uos_scan(dir / "scan001.3d", cloud);
  write_uos_pose(dir / "scan000.pose", Eigen::Isometry3d::Identity());
  expect_input_error([&] { open_dataset(dir.path()); }, dir / "scan001.pose", "", "missing odometry");
}

TEST(KittiDataset, SequenceFolder) {
  TempDir dir;
  const auto src = data_dir() / "kitti00_pair";
  std::filesystem::create_directories(dir / "velodyne");
  std::filesystem::copy_file(src / "000000.xyz32.bin", dir / "velodyne" / "000000.xyz32.bin");
  std::filesystem::copy_file(src / "000001.xyz32.bin", dir / "velodyne" / "000001.xyz32.bin");
  std::filesystem::copy_file(src / "kitti00_calib_Tr_velo_to_cam0.txt", dir / "calib.txt");
  std::filesystem::copy_file(src / "kitti00_poses_cam0_frames0-1.txt", dir / "poses.txt");
  write_text(dir / "times.txt", "0.0\n0.1036\n");
  const auto ds = open_dataset(dir.path());
  EXPECT_EQ(ds->metadata().format, "kitti");
  ASSERT_EQ(ds->size(), 2u);
  EXPECT_TRUE(ds->metadata().has_ground_truth);
  EXPECT_FALSE(ds->metadata().has_odometry);
  EXPECT_NEAR(*ds->stamp(1), 0.1036, 1e-12);
  EXPECT_EQ(ds->scan(1).size(), 124605u);
  const auto expected =
      kitti_velodyne_poses(read_kitti_poses(dir / "poses.txt"), read_kitti_calib_tr(dir / "calib.txt"));
  EXPECT_TRUE(ds->ground_truth(1)->isApprox(expected[1]));

  write_text(dir / "times.txt", "0.0\n");
  expect_input_error([&] { open_dataset(dir.path()); }, dir / "times.txt", "", "1 times for 2 scans");
  std::filesystem::remove(dir / "times.txt");
  std::filesystem::remove(dir / "calib.txt");
  expect_input_error([&] { open_dataset(dir.path()); }, dir / "calib.txt", "", "missing");
}

}  // namespace
}  // namespace sextant
