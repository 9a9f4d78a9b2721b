// A borrowed cloud reads another's memory until it is changed; copies always own their points.
#include <gtest/gtest.h>

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
