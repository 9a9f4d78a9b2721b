#pragma once
// Synthetic scenes for the matcher tests: boxes and planes sampled with points.
#include "sextant/core/point_cloud.hpp"
#include "sextant/core/rng.hpp"
#include "sextant_test/random_draws.hpp"

namespace sextant::test {

/// Points on an axis-aligned box's surface (no bottom), uniformly by area, noise σ [m].
inline void add_box(PointCloud& cloud, const Eigen::Vector3f& lo, const Eigen::Vector3f& hi, int n, Rng& rng,
                    double sigma = 0.0) {
  const Eigen::Vector3f d = hi - lo;
  const double areas[5] = {d.y() * d.z(), d.y() * d.z(), d.x() * d.z(), d.x() * d.z(), d.x() * d.y()};
  const double total = areas[0] + areas[1] + areas[2] + areas[3] + areas[4];
  for (int i = 0; i < n; ++i) {
    double pick = rng.uniform() * total;
    int face = 0;
    while (face < 4 && pick > areas[face]) pick -= areas[face++];
    const Eigen::Vector3f u = unit_draws(rng).cast<float>();
    Eigen::Vector3f p(lo.x() + d.x() * u.x(), lo.y() + d.y() * u.y(), lo.z() + d.z() * u.z());
    switch (face) {
      case 0: p.x() = lo.x(); break;
      case 1: p.x() = hi.x(); break;
      case 2: p.y() = lo.y(); break;
      case 3: p.y() = hi.y(); break;
      default: p.z() = hi.z(); break;
    }
    if (sigma > 0) p += normal_draws<3>(rng, sigma).cast<float>();
    cloud.push_back(p);
  }
}

/// A ground patch z = slope·x over [lo, hi] in x and y.
inline void add_ground(PointCloud& cloud, float lo, float hi, float slope, int n, Rng& rng) {
  for (int i = 0; i < n; ++i) {
    const auto x = static_cast<float>(rng.uniform(lo, hi)), y = static_cast<float>(rng.uniform(lo, hi));
    cloud.push_back({x, y, slope * x + 0.02f * static_cast<float>(rng.normal())});
  }
}

/// A small "yard": sloped ground, several buildings of different sizes, a wall — enough
/// structure in every direction for a unique registration. About `scale`·13,000 points.
inline PointCloud yard(Rng& rng, int scale = 1, float half = 25.0f) {
  PointCloud cloud;
  add_ground(cloud, -half, half, 0.03f, 4000 * scale, rng);
  add_box(cloud, {5, 4, 0}, {12, 9, 6}, 2000 * scale, rng, 0.01);
  add_box(cloud, {-15, -3, 0}, {-9, 8, 9}, 2000 * scale, rng, 0.01);
  add_box(cloud, {-3, -18, 0}, {9, -13, 4}, 2000 * scale, rng, 0.01);
  add_box(cloud, {14, -10, 0}, {16, -2, 3}, 1000 * scale, rng, 0.01);
  add_box(cloud, {-20, 14, 0}, {-12, 20, 7}, 1500 * scale, rng, 0.01);
  add_box(cloud, {2, 16, 0}, {3, 22, 2.5f}, 500 * scale, rng, 0.01);
  return cloud;
}

}  // namespace sextant::test
