// A borrowed cloud reads another's memory until it is changed; copies always own their points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "sextant/core/point_cloud.hpp"

namespace sextant {
namespace {

std::vector<Eigen::Vector3f> three_points() {
  return {{1, 2, 3}, {-4, 5, 6}, {7, -8, 9}};
}

TEST(PointCloud, ABorrowedCloudReadsTheMemoryInPlace) {
  const std::vector<Eigen::Vector3f> memory = three_points();
  const PointCloud cloud = PointCloud::borrow(memory.data(), memory.size());
  EXPECT_TRUE(cloud.borrowed());
  EXPECT_EQ(cloud.size(), 3u);
  EXPECT_EQ(cloud.points().data(), memory.data());  // no copy
  EXPECT_EQ(cloud.data(), memory.front().data());
  EXPECT_EQ(cloud[2], Eigen::Vector3f(7, -8, 9));
  EXPECT_EQ(cloud.bounds().min, Eigen::Vector3f(-4, -8, 3));
  EXPECT_EQ(cloud.subset({2, 0}).points(), PointsView(std::vector<Eigen::Vector3f>{memory[2], memory[0]}));
  EXPECT_FALSE(PointCloud::borrow(memory.data(), 0).borrowed());
}

/// The bounds one point at a time, std::min / std::max per coordinate (what bounds() must equal).
Bounds bounds_one_at_a_time(const std::vector<Eigen::Vector3f>& points) {
  Bounds b;
  if (points.empty()) return b;
  b.min = b.max = points.front();
  for (const Eigen::Vector3f& p : points)
    for (int a = 0; a < 3; ++a) b.min(a) = std::min(b.min(a), p(a)), b.max(a) = std::max(b.max(a), p(a));
  return b;
}

// bounds() takes four points at a time in twelve lanes: every size around a multiple of four, the
// extremes in every lane and in the tail, and a NaN coordinate (which, after a first number, never
// replaces one) must give the same box as one point at a time.
// A point without intensity in a cloud with intensity left the two arrays of different lengths, and
// a writer read past the end of the shorter (found by ASan).
TEST(PointCloud, EveryPointHasAnIntensityOrNoneHas) {
  PointCloud with;
  with.push_back(Eigen::Vector3f(1, 2, 3), 7.f);
  EXPECT_THROW(with.push_back(Eigen::Vector3f(4, 5, 6)), std::logic_error);
  EXPECT_EQ(with.size(), 1u);
  PointCloud without;
  without.push_back(Eigen::Vector3f(1, 2, 3));
  EXPECT_THROW(without.push_back(Eigen::Vector3f(4, 5, 6), 7.f), std::logic_error);
}

TEST(PointCloud, TimesAreOnePerPointAndFollowEveryPoint) {
  PointCloud cloud(std::vector<Eigen::Vector3f>{{1, 0, 0}, {2, 0, 0}, {3, 0, 0}});
  EXPECT_FALSE(cloud.has_time());
  EXPECT_THROW(cloud.set_time({0.f, 1.f}), std::invalid_argument);
  cloud.set_time({0.00f, 0.05f, 0.10f});
  ASSERT_TRUE(cloud.has_time());
  EXPECT_THROW(cloud.push_back(Eigen::Vector3f(4, 0, 0)), std::logic_error);
  EXPECT_THROW(cloud.push_back(Eigen::Vector3f(4, 0, 0), 1.f), std::logic_error);
  EXPECT_EQ(cloud.size(), 3u);

  const PointCloud picked = cloud.subset({2, 0});
  EXPECT_EQ(picked.time(), (std::vector<float>{0.10f, 0.00f}));
  EXPECT_EQ(cloud.transformed(Eigen::Isometry3d(Eigen::Translation3d(1, 2, 3))).time(), cloud.time());
  const PointCloud copy = cloud;
  EXPECT_EQ(copy.time(), cloud.time());

  PointCloud with_bad_time = cloud;
  with_bad_time.set_time({0.00f, std::numeric_limits<float>::quiet_NaN(), 0.10f});
  EXPECT_EQ(remove_non_finite(with_bad_time), 1u);
  EXPECT_EQ(with_bad_time.time(), (std::vector<float>{0.00f, 0.10f}));
  EXPECT_EQ(with_bad_time[1], Eigen::Vector3f(3, 0, 0));
  cloud.set_time({});
  EXPECT_FALSE(cloud.has_time());
}

TEST(PointCloud, BoundsAreThoseOfOnePointAtATime) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t n = 1; n <= 13; ++n)
    for (std::size_t extreme = 0; extreme < n; ++extreme)
      for (const bool with_nan : {false, true}) {
        std::vector<Eigen::Vector3f> points;
        for (std::size_t i = 0; i < n; ++i)
          points.emplace_back(static_cast<float>(i % 3), -static_cast<float>(i % 5),
                              0.5f * static_cast<float>(i));
        points[extreme] = Eigen::Vector3f(-100.0f - static_cast<float>(extreme), 50.0f, -7.0f);
        if (with_nan && n > 1) points[(extreme + 1) % n].y() = nan;
        const Bounds want = bounds_one_at_a_time(points);
        const Bounds got = PointCloud::borrow(points.data(), points.size()).bounds();
        for (int a = 0; a < 3; ++a) {
          const bool both_nan = std::isnan(want.min(a)) && std::isnan(got.min(a));
          EXPECT_TRUE(both_nan || got.min(a) == want.min(a)) << "n " << n << ", extreme " << extreme;
          EXPECT_TRUE(std::isnan(want.max(a)) ? std::isnan(got.max(a)) : got.max(a) == want.max(a))
              << "n " << n << ", extreme " << extreme;
        }
      }
}

TEST(PointCloud, ChangingABorrowedCloudCopiesItFirst) {
  std::vector<Eigen::Vector3f> memory = three_points();
  PointCloud cloud = PointCloud::borrow(memory.data(), memory.size());
  cloud.push_back(Eigen::Vector3f(0, 0, 1));
  EXPECT_FALSE(cloud.borrowed());
  EXPECT_EQ(cloud.size(), 4u);
  EXPECT_EQ(memory.size(), 3u);  // the lender is untouched
  cloud[0] = Eigen::Vector3f::Zero();
  EXPECT_EQ(memory[0], Eigen::Vector3f(1, 2, 3));
}

TEST(PointCloud, ACopyOfABorrowedCloudOwnsItsPoints) {
  std::vector<Eigen::Vector3f> memory = three_points();
  const PointCloud borrowed = PointCloud::borrow(memory.data(), memory.size());
  PointCloud copy(borrowed);
  PointCloud assigned;
  assigned = borrowed;
  memory[1] = Eigen::Vector3f::Constant(100);  // the lender changes after the copies
  for (const PointCloud* c : {&copy, &assigned}) {
    EXPECT_FALSE(c->borrowed());
    EXPECT_EQ((*c)[1], Eigen::Vector3f(-4, 5, 6));
  }
  EXPECT_EQ(borrowed[1], Eigen::Vector3f::Constant(100));
}

TEST(PointCloud, RemovingNothingKeepsABorrowedCloudBorrowed) {
  std::vector<Eigen::Vector3f> memory = three_points();
  PointCloud cloud = PointCloud::borrow(memory.data(), memory.size());
  EXPECT_EQ(remove_non_finite(cloud), 0u);
  EXPECT_TRUE(cloud.borrowed());
  memory[1].x() = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(remove_non_finite(cloud), 1u);
  EXPECT_FALSE(cloud.borrowed());
  EXPECT_EQ(cloud.size(), 2u);
  EXPECT_EQ(cloud[1], Eigen::Vector3f(7, -8, 9));
  EXPECT_TRUE(std::isnan(memory[1].x()));  // the lender still has its row
}

}  // namespace
}  // namespace sextant
