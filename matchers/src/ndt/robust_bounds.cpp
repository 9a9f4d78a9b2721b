// The box the ML-NDT layers split (ndt_grid.hpp's robust_bounds): the bounding box without its
// farthest points, so that one stray point or a few gross outliers do not set the cell sizes.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

#include "sextant/matchers/ndt_grid.hpp"

namespace sextant {
namespace {

/// The k-th of `values` in the order `before` (1 ≤ k ≤ values.size()): exactly the value
/// std::nth_element would place at rank k − 1. A strided subsample gives a bound a little beyond
/// the k-th; the values up to that bound (a few hundred where k is a small fraction) are all that
/// need ordering. When the bound falls short of k values, all of them are ordered.
template <class Before>
float kth(const std::vector<float>& values, std::size_t k, Before before) {
  const std::size_t m = values.size();
  constexpr std::size_t kSubsample = 256;
  std::vector<float> pool;
  if (m > 4 * kSubsample) {
    const std::size_t stride = m / kSubsample;
    std::vector<float> sub;
    sub.reserve(m / stride + 1);
    for (std::size_t i = 0; i < m; i += stride) sub.push_back(values[i]);
    // The subsample's rank of the k-th, with a margin of three standard deviations of a binomial
    // count and a few values more.
    const double expected = static_cast<double>(k) * static_cast<double>(sub.size()) / static_cast<double>(m);
    const auto rank =
        std::min(sub.size() - 1, static_cast<std::size_t>(expected + 3.0 * std::sqrt(expected) + 8.0));
    std::nth_element(sub.begin(), sub.begin() + static_cast<std::ptrdiff_t>(rank), sub.end(), before);
    const float bound = sub[rank];
    for (const float v : values)
      if (!before(bound, v)) pool.push_back(v);  // v at or before the bound
  }
  if (pool.size() < k) pool = values;  // the bound fell short (or a small input): order them all
  std::nth_element(pool.begin(), pool.begin() + static_cast<std::ptrdiff_t>(k - 1), pool.end(), before);
  return pool[k - 1];
}

}  // namespace

Bounds robust_bounds(const PointCloud& cloud, double quantile) {
  const Bounds box = cloud.bounds();
  if (!(quantile > 0.0) || cloud.size() < 2) return box;
  constexpr std::size_t kMaxSample = 16384;
  const std::size_t stride = (cloud.size() + kMaxSample - 1) / kMaxSample;
  std::vector<float> values[3];  // the finite coordinates of every stride-th point, per axis
  for (std::vector<float>& v : values) v.reserve(cloud.size() / stride + 1);
  for (std::size_t i = 0; i < cloud.size(); i += stride)
    for (int a = 0; a < 3; ++a)
      if (std::isfinite(cloud[i](a))) values[a].push_back(cloud[i](a));
  Bounds robust;
  for (int a = 0; a < 3; ++a) {
    if (values[a].empty()) return box;
    // The values of rank floor(q·(m − 1)) and floor((1 − q)·(m − 1)) in the sorted values: the
    // (rank + 1)-th smallest and the (m − rank)-th largest.
    const std::size_t m = values[a].size();
    const auto rank = [&](double q) { return static_cast<std::size_t>(q * static_cast<double>(m - 1)); };
    const float low = kth(values[a], rank(quantile) + 1, std::less<float>());
    const float high = kth(values[a], m - rank(1.0 - quantile), std::greater<float>());
    const float margin = 0.1f * (high - low);
    robust.min(a) = std::max(box.min(a), low - margin);
    robust.max(a) = std::min(box.max(a), high + margin);
  }
  return robust;
}

}  // namespace sextant
