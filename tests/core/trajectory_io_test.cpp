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
