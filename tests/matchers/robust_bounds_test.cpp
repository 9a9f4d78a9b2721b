// robust_bounds selects its quantiles without ordering the whole sample (robust_bounds.cpp): the box
// must be exactly the one the plain order statistics give, whatever order the points come in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "sextant/core/rng.hpp"
#include "sextant/matchers/ndt_grid.hpp"

namespace sextant {
namespace {

/// ndt_grid.hpp's definition, by std::nth_element over the whole strided sample.
Bounds by_order_statistics(const PointCloud& cloud, double quantile) {
  const Bounds box = cloud.bounds();
  const std::size_t stride = (cloud.size() + 16383) / 16384;
  Bounds robust;
  for (int a = 0; a < 3; ++a) {
    std::vector<float> v;
    for (std::size_t i = 0; i < cloud.size(); i += stride)
      if (std::isfinite(cloud[i](a))) v.push_back(cloud[i](a));
    const std::size_t m = v.size();
    const auto rank = [&](double q) { return static_cast<std::size_t>(q * static_cast<double>(m - 1)); };
    std::vector<float> ascending = v, descending = v;
    const std::size_t low_rank = rank(quantile), high_rank = m - rank(1.0 - quantile) - 1;
    std::nth_element(ascending.begin(), ascending.begin() + static_cast<std::ptrdiff_t>(low_rank),
                     ascending.end());
    std::nth_element(descending.begin(), descending.begin() + static_cast<std::ptrdiff_t>(high_rank),
                     descending.end(), std::greater<float>());
    const float low = ascending[low_rank], high = descending[high_rank];
    robust.min(a) = std::max(box.min(a), low - 0.1f * (high - low));
    robust.max(a) = std::min(box.max(a), high + 0.1f * (high - low));
  }
  return robust;
}

// Sizes below and above the subsample's threshold and the 16,384-point stride; points in random
// order, sorted either way, in a lidar's sweep order, with many equal values, with a NaN, and an
// order that puts the smallest values exactly on the subsample's stride (the bound then falls short
// of the quantile at q = 0.2 and every value is ordered).
TEST(RobustBounds, QuantilesAreTheExactOrderStatistics) {
  Rng rng(3);
  for (const std::size_t n : {50u, 900u, 5000u, 16384u, 40001u})
    for (int order = 0; order < 6; ++order)
      for (const double quantile : {0.005, 0.2}) {
        std::vector<Eigen::Vector3f> points;
        for (std::size_t i = 0; i < n; ++i) {
          const double t = static_cast<double>(i) / static_cast<double>(n);
          Eigen::Vector3f p(static_cast<float>(rng.normal(0.0, 20.0)),
                            static_cast<float>(30.0 * std::cos(12.0 * t)),
                            static_cast<float>(std::floor(rng.uniform(0.0, 4.0))));
          if (order == 3) p.x() = (i % 256 == 0) ? -1000.0f : static_cast<float>(i);
          points.push_back(p);
        }
        if (order == 1)
          std::sort(points.begin(), points.end(), [](auto& a, auto& b) { return a.x() < b.x(); });
        if (order == 2)
          std::sort(points.begin(), points.end(), [](auto& a, auto& b) { return a.x() > b.x(); });
        if (order == 4) points[n / 3].y() = std::numeric_limits<float>::quiet_NaN();
        if (order == 5) points[0] = Eigen::Vector3f(1e4f, -1e4f, 1e4f);  // a stray point
        const PointCloud cloud = PointCloud::borrow(points.data(), points.size());
        const Bounds want = by_order_statistics(cloud, quantile), got = robust_bounds(cloud, quantile);
        EXPECT_EQ(got.min, want.min) << "n " << n << ", order " << order << ", quantile " << quantile;
        EXPECT_EQ(got.max, want.max) << "n " << n << ", order " << order << ", quantile " << quantile;
      }
}

}  // namespace
}  // namespace sextant
