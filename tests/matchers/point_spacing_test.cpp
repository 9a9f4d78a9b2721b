// The nearest-neighbour spacing of a scan (point_spacing.hpp) on clouds whose spacing is known.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sextant/core/rng.hpp"
#include "sextant/matchers/point_spacing.hpp"

namespace sextant {
namespace {

/// A square grid of n × n points `spacing` apart on the plane z = height.
PointCloud plane_grid(int n, double spacing, double height = 0.0) {
  PointCloud cloud;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      cloud.push_back(Eigen::Vector3f(static_cast<float>(i * spacing), static_cast<float>(j * spacing),
                                      static_cast<float>(height)));
  return cloud;
}

TEST(PointSpacing, AGridsSpacingIsItsStep) {
  for (const double step : {0.01, 0.1, 0.37, 2.0}) {
    const PointSpacing s = measure_point_spacing(plane_grid(60, step));
    EXPECT_NEAR(s.median, step, 1e-5 * step + 1e-6) << step;
    EXPECT_EQ(s.finite, 3600u);
    EXPECT_EQ(s.queried, 1800u);  // every second point: at most 2000 queries
  }
}

TEST(PointSpacing, JitterLeavesTheMedianNearTheStep) {
  // Points 0.2 m apart, each moved by up to ±1 cm per axis: the nearest neighbour lies 0.18–0.22 m away.
  PointCloud cloud = plane_grid(80, 0.2);
  Rng rng(7);
  for (std::size_t i = 0; i < cloud.size(); ++i)
    cloud.mutable_points()[i] += Eigen::Vector3f(static_cast<float>(rng.uniform(-0.01, 0.01)),
                                                 static_cast<float>(rng.uniform(-0.01, 0.01)),
                                                 static_cast<float>(rng.uniform(-0.01, 0.01)));
  const PointSpacing s = measure_point_spacing(cloud, 10000);
  EXPECT_GT(s.median, 0.18);
  EXPECT_LT(s.median, 0.2);  // the nearest of four neighbours is closer than the mean distance
}

TEST(PointSpacing, ADenserSecondLayerHalvesItOnlyWhereItIs) {
  // Two planes 5 m apart, 0.1 m and 0.4 m grids of equally many points: half the points see 0.1 m, half
  // 0.4 m, and the median lies between them (nth_element takes the upper middle: 0.4 m).
  PointCloud cloud = plane_grid(40, 0.1);
  const PointCloud sparse = plane_grid(40, 0.4, 5.0);
  for (const Eigen::Vector3f& p : sparse.points()) cloud.push_back(p);
  const PointSpacing s = measure_point_spacing(cloud, 100000);
  EXPECT_EQ(s.queried, 3200u);
  EXPECT_NEAR(s.median, 0.4, 1e-5);
}

TEST(PointSpacing, DuplicatesAndNonFinitePoints) {
  PointCloud cloud = plane_grid(10, 0.5);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud.push_back(Eigen::Vector3f(nan, 0.0f, 0.0f));
  EXPECT_EQ(measure_point_spacing(cloud).finite, 100u);
  EXPECT_NEAR(measure_point_spacing(cloud).median, 0.5, 1e-6);
  PointCloud doubled = plane_grid(10, 0.5);
  const PointCloud twins = plane_grid(10, 0.5);  // a named copy: a temporary's points() would dangle
  for (const Eigen::Vector3f& p : twins.points()) doubled.push_back(p);
  EXPECT_EQ(measure_point_spacing(doubled).median, 0.0);  // every point has a twin
  EXPECT_EQ(measure_point_spacing(PointCloud()).median, 0.0);
  PointCloud one;
  one.push_back(Eigen::Vector3f::Zero());
  EXPECT_EQ(measure_point_spacing(one).queried, 0u);
}

}  // namespace
}  // namespace sextant
