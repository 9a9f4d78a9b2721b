#include <gtest/gtest.h>

#include "sextant/core/io/trajectory_io.hpp"
#include "sextant/core/pose.hpp"
#include "test_util.hpp"

namespace sextant {
namespace {

using test::expect_input_error;
using test::TempDir;
using test::write_text;

Trajectory sample_trajectory() {
  return {{1.5, to_isometry({1, 2, 3, 0.1, -0.2, 0.3})}, {2.25, to_isometry({-4, 0.5, 6, 0.0, 1.2, -3.0})}};
}

TEST(TrajectoryIo, TumRoundTrip) {
  TempDir dir;
  write_tum_trajectory(dir / "t.tum", sample_trajectory());
  const Trajectory back = read_tum_trajectory(dir / "t.tum");
  ASSERT_EQ(back.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_DOUBLE_EQ(back[i].stamp, sample_trajectory()[i].stamp);
    EXPECT_TRUE(back[i].pose.isApprox(sample_trajectory()[i].pose, 1e-7));
  }
}

TEST(TrajectoryIo, TumKnownLine) {
  // evo / TUM: "timestamp tx ty tz qx qy qz qw"; a 90° yaw is q = (0, 0, sin 45°, cos 45°).
  TempDir dir;
  write_text(dir / "k.txt", "# comment\n10.0 1 2 3 0 0 0.7071067811865476 0.7071067811865476\n");
  const Trajectory t = read_tum_trajectory(dir / "k.txt");
  ASSERT_EQ(t.size(), 1u);
  EXPECT_NEAR((t[0].pose.linear() * Eigen::Vector3d::UnitX()).y(), 1.0, 1e-12);
  EXPECT_TRUE(t[0].pose.translation().isApprox(Eigen::Vector3d(1, 2, 3)));
}

// A trajectory is a time series: lines out of time order are read in time order, and say so; a stamp
// given twice is an error naming both lines (issue 64: the RPE and drift were taken along the lines).
TEST(TrajectoryIo, TumLinesAreTakenInTimeOrder) {
  TempDir dir;
  write_text(
      dir / "s.tum",
      "3 3 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n# a comment\n2 2 0 0 0 0 0 1\n4 4 0 0 0 0 0 1\n0 0 0 0 0 0 0 1\n");
  TrajectoryReadNotes notes;
  const Trajectory t = read_tum_trajectory(dir / "s.tum", &notes);
  ASSERT_EQ(t.size(), 5u);
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_EQ(t[i].stamp, static_cast<double>(i));
    EXPECT_EQ(t[i].pose.translation().x(), static_cast<double>(i));  // each pose stays with its stamp
  }
  EXPECT_EQ(notes.out_of_order, 3u);  // the lines of stamps 1, 2 and 0 come after a later one
  EXPECT_NE(trajectory_note(dir / "s.tum", notes).find("3 poses come after a later stamp"),
            std::string::npos);
  TrajectoryReadNotes again;
  read_trajectory(dir / "s.tum", &again);
  EXPECT_EQ(again.out_of_order, 3u);
  TrajectoryReadNotes ordered;
  write_tum_trajectory(dir / "o.tum", sample_trajectory());
  read_tum_trajectory(dir / "o.tum", &ordered);
  EXPECT_EQ(ordered.out_of_order, 0u);
  EXPECT_EQ(trajectory_note(dir / "o.tum", ordered), "");
  write_text(dir / "d.tum", "1 0 0 0 0 0 0 1\n2 0 0 0 0 0 0 1\n1 5 0 0 0 0 0 1\n");
  expect_input_error([&] { read_tum_trajectory(dir / "d.tum"); }, dir / "d.tum", "line 3",
                     "(also at line 1)");
}

TEST(TrajectoryIo, KittiRoundTrip) {
  TempDir dir;
  write_kitti_trajectory(dir / "k.txt", sample_trajectory());
  const Trajectory back = read_kitti_trajectory(dir / "k.txt");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_DOUBLE_EQ(back[1].stamp, 1.0);
  EXPECT_TRUE(back[1].pose.isApprox(sample_trajectory()[1].pose, 1e-7));
}

TEST(TrajectoryIo, BadInput) {
  TempDir dir;
  write_text(dir / "a.txt", "1 2 3 4 0 0 0 1\n1 2 3\n");
  expect_input_error([&] { read_tum_trajectory(dir / "a.txt"); }, dir / "a.txt", "line 2", "expected 8");
  write_text(dir / "b.txt", "1 2 3 4 0 0 0 2\n");
  expect_input_error([&] { read_tum_trajectory(dir / "b.txt"); }, dir / "b.txt", "line 1", "quaternion norm");
  write_text(dir / "c.txt", "1 2 3 4 0 0 0 1e\n");
  expect_input_error([&] { read_tum_trajectory(dir / "c.txt"); }, dir / "c.txt", "line 1", "'1e'");
  expect_input_error([&] { read_kitti_trajectory(dir / "none.txt"); }, dir / "none.txt", "", "cannot open");
}

}  // namespace
}  // namespace sextant
