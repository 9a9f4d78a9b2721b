// Any folder of scans as a dataset (open_scan_folder), and what every folder layout reports about
// its numbering: gaps and mixed formats as notes, two files with one number as an error.
#include <gtest/gtest.h>

#include <algorithm>

#include "sextant/core/dataset.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/io/kitti.hpp"
#include "sextant/core/io/trajectory_io.hpp"
#include "sextant/core/io/uos.hpp"
#include "test_util.hpp"

namespace sextant {
namespace {

using test::expect_input_error;
using test::TempDir;
using test::write_text;

/// A cloud of `n` points, its first at (n, 0, 0), so that the scan can be recognised by its size.
PointCloud cloud_of(std::size_t n) {
  PointCloud cloud;
  for (std::size_t i = 0; i < n; ++i) cloud.push_back({static_cast<float>(n + i), 1.f, 2.f});
  return cloud;
}

bool has_note(const DatasetMetadata& m, const std::string& part) {
  return std::any_of(m.notes.begin(), m.notes.end(),
                     [&](const std::string& note) { return note.find(part) != std::string::npos; });
}

TEST(ScanFolder, NaturalOrderOfAnyFormat) {
  TempDir dir;
  write_cloud(dir / "full10.pcd", cloud_of(10));
  write_cloud(dir / "full2.ply", cloud_of(2));
  write_cloud(dir / "full3.xyz", cloud_of(3));
  write_text(dir / "readme.txt", "not a scan\n");
  const auto ds = open_dataset(dir.path());
  EXPECT_EQ(ds->metadata().format, "folder");
  ASSERT_EQ(ds->size(), 3u);
  EXPECT_EQ(ds->scan_file(0).filename(), "full2.ply");
  EXPECT_EQ(ds->scan_file(1).filename(), "full3.xyz");
  EXPECT_EQ(ds->scan_file(2).filename(), "full10.pcd");
  EXPECT_EQ(ds->scan(2).size(), 10u);
  EXPECT_FALSE(ds->metadata().has_ground_truth);
  EXPECT_FALSE(ds->ground_truth(0).has_value());
  EXPECT_FALSE(ds->stamp(0).has_value());
  EXPECT_TRUE(has_note(ds->metadata(), "6 numbers missing: 4–9")) << ds->metadata().notes.size();
  EXPECT_TRUE(has_note(ds->metadata(), "mix file formats (1 .pcd, 1 .ply, 1 .xyz)"));
}

TEST(ScanFolder, NamesThatAreTimesOrderByTheirValueAndStampTheScans) {
  TempDir dir;
  write_cloud(dir / "1565943695.9.pcd", cloud_of(3));
  write_cloud(dir / "1565943696.1.pcd", cloud_of(4));
  write_cloud(dir / "1565943695.228028.pcd", cloud_of(2));
  write_cloud(dir / "1565943695.05.pcd", cloud_of(1));
  write_cloud(dir / "1565943695.000.pcd", cloud_of(5));
  const auto ds = open_dataset(dir.path());
  ASSERT_EQ(ds->size(), 5u);
  const std::vector<std::string> order{"1565943695.000.pcd", "1565943695.05.pcd", "1565943695.228028.pcd",
                                       "1565943695.9.pcd", "1565943696.1.pcd"};
  for (std::size_t i = 0; i < order.size(); ++i) EXPECT_EQ(ds->scan_file(i).filename(), order[i]) << i;
  ASSERT_TRUE(ds->stamp(2).has_value());
  EXPECT_DOUBLE_EQ(*ds->stamp(0), 1565943695.0);
  EXPECT_NEAR(*ds->stamp(2), 1565943695.228028, 1e-6);
  EXPECT_NEAR(*ds->stamp(4), 1565943696.1, 1e-6);
  EXPECT_FALSE(has_note(ds->metadata(), "missing")) << "times are not counts: no gaps";
  EXPECT_TRUE(has_note(ds->metadata(), "times are the numbers in their names"));

  write_text(dir / "times.txt", "0\n0.1\n0.2\n0.3\n0.4\n");
  EXPECT_DOUBLE_EQ(*open_dataset(dir.path())->stamp(4), 0.4) << "times.txt replaces the names' times";
}

TEST(ScanFolder, ANumberWrittenTwiceWithAndWithoutItsFractionIsAmbiguous) {
  TempDir dir;
  write_cloud(dir / "cloud_12.pcd", cloud_of(2));
  write_cloud(dir / "cloud_12.00.pcd", cloud_of(3));
  expect_input_error([&] { open_dataset(dir.path()); }, dir.path().string(), "", "both carry the number 12");
}

TEST(ScanFolder, IntegerAndFractionNamesMixByValueWithoutStamps) {
  TempDir dir;
  write_cloud(dir / "scan_2.pcd", cloud_of(2));
  write_cloud(dir / "scan_1.5.pcd", cloud_of(3));
  write_cloud(dir / "scan_1.pcd", cloud_of(4));
  const auto ds = open_dataset(dir.path());
  EXPECT_EQ(ds->scan_file(0).filename(), "scan_1.pcd");
  EXPECT_EQ(ds->scan_file(1).filename(), "scan_1.5.pcd");
  EXPECT_EQ(ds->scan_file(2).filename(), "scan_2.pcd");
  EXPECT_FALSE(ds->stamp(0).has_value()) << "only names that are all times stamp the scans";
}

TEST(ScanFolder, ScansSubfolderWithPosesAndTimes) {
  TempDir dir;
  for (int i = 0; i < 3; ++i)
    write_cloud(dir / "scans" / ("00000" + std::to_string(i) + ".pcd"), cloud_of(4 + i));
  std::vector<Eigen::Isometry3d> poses(3, Eigen::Isometry3d::Identity());
  poses[1].translation() = Eigen::Vector3d(1.5, 0, 0);
  poses[2].translation() = Eigen::Vector3d(3.0, 0.5, 0);
  poses[2].linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  write_kitti_poses(dir / "poses.txt", poses);
  write_text(dir / "times.txt", "10.0\n10.5\n12.25\n");
  const auto ds = open_dataset(dir.path());
  ASSERT_EQ(ds->size(), 3u);
  EXPECT_TRUE(ds->metadata().notes.empty());
  EXPECT_EQ(ds->scan(1).size(), 5u);
  ASSERT_TRUE(ds->metadata().has_ground_truth);
  // poses.txt of a scan folder is world ← scan as it stands: no camera calibration applied.
  EXPECT_TRUE(ds->ground_truth(2)->isApprox(poses[2], 1e-9));
  EXPECT_DOUBLE_EQ(*ds->stamp(2), 12.25);

  write_text(dir / "times.txt", "10.0\n10.5\n");
  expect_input_error([&] { open_dataset(dir.path()); }, dir / "times.txt", "", "2 times for 3 scans");
  std::filesystem::remove(dir / "times.txt");
  poses.pop_back();
  write_kitti_poses(dir / "poses.txt", poses);
  expect_input_error([&] { open_dataset(dir.path()); }, dir / "poses.txt", "", "2 poses for 3 scans");
}

TEST(ScanFolder, PosesFileInTumOrKittiFormat) {
  TempDir dir;
  for (int i = 0; i < 2; ++i) write_cloud(dir / ("s" + std::to_string(i) + ".csv"), cloud_of(3));
  Trajectory truth(2);
  truth[1].stamp = 0.1;
  truth[1].pose.translation() = Eigen::Vector3d(0.2, -0.1, 0.05);
  truth[1].pose.linear() = Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  write_tum_trajectory(dir / "gt.tum", truth);
  const auto tum = open_scan_folder(dir.path(), dir / "gt.tum");
  EXPECT_TRUE(tum->ground_truth(1)->isApprox(truth[1].pose, 1e-6));
  write_kitti_trajectory(dir / "gt.kitti", truth);
  const auto kitti = open_scan_folder(dir.path(), dir / "gt.kitti");
  EXPECT_TRUE(kitti->ground_truth(1)->isApprox(truth[1].pose, 1e-6));
  write_text(dir / "bad.txt", "1 2 3 4 5\n");
  expect_input_error([&] { open_scan_folder(dir.path(), dir / "bad.txt"); }, dir / "bad.txt", "line 1",
                     "found 5 numbers");
}

// Order is by time (issue 64): the scans' times increase; a TUM file's poses pair with the scans by
// their stamps, whatever the order of its lines, and stamps that are not the scans' times are refused.
TEST(ScanFolder, PosesPairWithTheScansByTime) {
  TempDir dir;
  for (int i = 0; i < 3; ++i) write_cloud(dir / ("s" + std::to_string(i) + ".csv"), cloud_of(3));
  write_text(dir / "times.txt", "10.0\n10.5\n11.0\n");
  Trajectory truth(3);
  for (int i = 0; i < 3; ++i) {
    truth[static_cast<std::size_t>(i)].stamp = 10.0 + 0.5 * i;
    truth[static_cast<std::size_t>(i)].pose.translation() = Eigen::Vector3d(i, 0, 0);
  }
  Trajectory reversed(truth.rbegin(), truth.rend());
  write_tum_trajectory(dir / "reversed.tum", reversed);
  const auto ds = open_scan_folder(dir.path(), dir / "reversed.tum");
  for (int i = 0; i < 3; ++i) EXPECT_EQ(ds->ground_truth(static_cast<std::size_t>(i))->translation().x(), i);
  EXPECT_TRUE(has_note(ds->metadata(), "2 poses come after a later stamp"));
  Trajectory late = truth;
  for (StampedPose& p : late) p.stamp += 5000.0;  // another clock
  write_tum_trajectory(dir / "late.tum", late);
  expect_input_error([&] { open_scan_folder(dir.path(), dir / "late.tum"); }, dir / "late.tum", "",
                     "the pose of scan 0 is stamped 5010");
  write_text(dir / "times.txt", "10.0\n10.5\n10.5\n");
  expect_input_error([&] { open_dataset(dir.path()); }, dir / "times.txt", "line 3",
                     "is not after the previous");
  write_text(dir / "times.txt", "10.0\n9.5\n11.0\n");
  expect_input_error([&] { open_dataset(dir.path()); }, dir / "times.txt", "line 2",
                     "is not after the previous");
}

TEST(ScanFolder, SameNumberTwiceIsRefusedNamingBothFiles) {
  TempDir dir;
  write_cloud(dir / "cloud_001.pcd", cloud_of(3));
  write_cloud(dir / "cloud_1.ply", cloud_of(3));
  expect_input_error([&] { open_dataset(dir.path()); }, dir.path(), "", "cloud_001.pcd and cloud_1.ply");
}

TEST(ScanFolder, EmptyFolderAndMissingFolder) {
  TempDir dir;
  expect_input_error([&] { open_dataset(dir.path()); }, dir.path(), "", "no scans");
  expect_input_error([&] { open_dataset(dir / "nope"); }, dir / "nope", "", "not a folder");
}

TEST(ScanFolder, UosGapsAndAmbiguousNamesAreReported) {
  TempDir dir;
  for (const char* name : {"scan000.3d", "scan005.3d", "scan009.3d"}) write_uos_scan(dir / name, cloud_of(2));
  const auto ds = open_dataset(dir.path());
  EXPECT_EQ(ds->metadata().format, "uos");
  EXPECT_TRUE(has_note(ds->metadata(), "7 numbers missing: 1–4, 6–8"));
  write_uos_scan(dir / "scan5.3d", cloud_of(2));
  expect_input_error([&] { open_dataset(dir.path()); }, dir.path(), "", "scan005.3d and scan5.3d");
}

// Issue 64, class 4: every point-cloud file of a scan folder is accounted for. A file without a
// number in its name is left out with a note that names it; a link to nothing is refused (the scan
// it stands for cannot be read); clouds in the folder and in scans/ are refused as ambiguous.
TEST(ScanFolder, EveryCloudFileIsAccountedFor) {
  TempDir dir;
  write_cloud(dir / "seq" / "cloud_000.pcd", cloud_of(2));
  write_cloud(dir / "seq" / "cloud_001.pcd", cloud_of(3));
  write_cloud(dir / "seq" / "first.pcd", cloud_of(4));
  const auto ds = open_dataset(dir / "seq");
  EXPECT_EQ(ds->size(), 2u);
  EXPECT_TRUE(has_note(ds->metadata(),
                       "1 point-cloud file is not a scan of the sequence: first.pcd (no number "
                       "in its name, which orders the scans)"));

  std::filesystem::create_symlink(dir / "gone.pcd", dir / "seq" / "cloud_002.pcd");
  expect_input_error([&] { open_dataset(dir / "seq"); }, dir / "seq" / "cloud_002.pcd", "",
                     "a link to nothing");
  std::filesystem::remove(dir / "seq" / "cloud_002.pcd");

  write_cloud(dir / "seq" / "scans" / "000000.pcd", cloud_of(5));
  expect_input_error([&] { open_dataset(dir / "seq"); }, dir / "seq", "",
                     "both the folder (2 scans) and scans/ inside it (1) hold scans");

  // Only numberless clouds beside scans/: the scans are scans/'s, and the others are named.
  write_cloud(dir / "mulran" / "map.pcd", cloud_of(6));
  write_cloud(dir / "mulran" / "scans" / "000000.pcd", cloud_of(2));
  write_cloud(dir / "mulran" / "scans" / "000001.pcd", cloud_of(3));
  const auto inner = open_dataset(dir / "mulran");
  EXPECT_EQ(inner->size(), 2u);
  EXPECT_TRUE(has_note(inner->metadata(),
                       "in the folder itself: 1 point-cloud file is not a scan of the "
                       "sequence: map.pcd"));
  // Nothing but numberless clouds: no scans, and the error says why each file is not one.
  write_cloud(dir / "named" / "left.pcd", cloud_of(2));
  write_cloud(dir / "named" / "right.pcd", cloud_of(2));
  expect_input_error([&] { open_dataset(dir / "named"); }, dir / "named", "",
                     "2 point-cloud files are not a scan of the sequence: left.pcd (no number");
}

TEST(ScanFolder, KittiVelodyneMixingFormatsIsReported) {
  TempDir dir;
  write_xyz32(dir / "velodyne" / "000000.xyz32.bin", cloud_of(2));
  write_xyz32(dir / "velodyne" / "000001.xyz32.bin", cloud_of(3));
  write_kitti_velodyne(dir / "velodyne" / "000002.bin", cloud_of(4));
  const auto ds = open_dataset(dir.path());
  ASSERT_EQ(ds->size(), 3u);  // all three, in order, not the two .xyz32.bin alone
  EXPECT_EQ(ds->scan(2).size(), 4u);
  EXPECT_TRUE(has_note(ds->metadata(), "1 .bin, 2 .xyz32.bin"));
  write_kitti_velodyne(dir / "velodyne" / "000001.bin", cloud_of(4));
  expect_input_error([&] { open_dataset(dir.path()); }, (dir / "velodyne").string(), "",
                     "000001.bin and 000001.xyz32.bin");
}

}  // namespace
}  // namespace sextant

namespace sextant {
namespace {

// Issue 23: every pose read is a rigid transform, or an error naming the file and line.
TEST(PoseFiles, NonRigidPosesAreRefusedNamingTheLine) {
  TempDir dir;
  write_text(dir / "zeros.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n0 0 0 0 0 0 0 0 0 0 0 0\n");
  expect_input_error([&] { read_kitti_poses(dir / "zeros.txt"); }, dir / "zeros.txt", "line 2",
                     "not a rigid transform: the rotation is not orthonormal");
  write_text(dir / "mirror.txt", "-1 0 0 0 0 1 0 0 0 0 1 0\n");
  expect_input_error([&] { read_kitti_poses(dir / "mirror.txt"); }, dir / "mirror.txt", "line 1",
                     "reflection");
  write_text(dir / "rounded.txt",
             "0.999903 -0.0116068 -0.00770509 -1.9494 0.0115921 0.999931 -0.00195905 "
             "-0.0144169 0.0077273 0.00186954 0.999968 0.0611163\n");
  EXPECT_EQ(read_kitti_poses(dir / "rounded.txt").size(), 1u);  // 6 digits, as MulRan's poses.txt
  write_text(dir / "scan000.frames",
             "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 2\n0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 1 2\n");
  expect_input_error([&] { read_uos_frames(dir / "scan000.frames"); }, dir / "scan000.frames", "line 2",
                     "not a rigid transform");
  // A scan folder's poses.txt goes through the same reader.
  write_cloud(dir / "s" / "0.pcd", cloud_of(3));
  write_text(dir / "s" / "poses.txt", "0 0 0 0 0 0 0 0 0 0 0 0\n");
  expect_input_error([&] { open_dataset(dir / "s"); }, dir / "s" / "poses.txt", "line 1",
                     "not a rigid transform");
}

}  // namespace
}  // namespace sextant
