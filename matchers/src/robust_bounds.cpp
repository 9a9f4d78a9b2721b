// The box the ML-NDT layers split (ndt_grid.hpp's robust_bounds): the bounding box without its
// farthest points, so that one stray point or a few gross outliers do not set the cell sizes.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <queue>
#include <vector>

#include "sextant/matchers/ndt_grid.hpp"

namespace sextant {
namespace {

/// The k-th of `values` in the order `before` (k ≥ 1, k ≤ values.size()): one pass that keeps the
/// k first seen so far in a heap, the k-th on top. Exactly the value std::nth_element would place
/// at rank k − 1, at a fraction of its cost when k is small.
template <class Before>
float kth(const std::vector<float>& values, std::size_t k, Before before) {
  std::priority_queue<float, std::vector<float>, Before> first(before);
  for (const float v : values) {
    if (first.size() < k) {
      first.push(v);
    } else if (before(v, first.top())) {
      first.pop();
      first.push(v);
    }
  }
  return first.top();
}

}  // namespace

Bounds robust_bounds(const PointCloud& cloud, double quantile) {
  const Bounds box = cloud.bounds();
  if (!(quantile > 0.0) || cloud.size() < 2) return box;
  constexpr std::size_t kMaxSample = 16384;
  const std::size_t stride = (cloud.size() + kMaxSample - 1) / kMaxSample;
  std::vector<float> values;
  values.reserve(cloud.size() / stride + 1);
  Bounds robust;
  for (int a = 0; a < 3; ++a) {
    values.clear();
    for (std::size_t i = 0; i < cloud.size(); i += stride) {
      const float v = cloud[i](a);
      if (std::isfinite(v)) values.push_back(v);
    }
    if (values.empty()) return box;
    // The values of rank floor(q·(m − 1)) and floor((1 − q)·(m − 1)) in the sorted values: the
    // (rank + 1)-th smallest and the (m − rank)-th largest.
    const std::size_t m = values.size();
    const auto rank = [&](double q) { return static_cast<std::size_t>(q * static_cast<double>(m - 1)); };
    const float low = kth(values, rank(quantile) + 1, std::less<float>());
    const float high = kth(values, m - rank(1.0 - quantile), std::greater<float>());
    const float margin = 0.1f * (high - low);
    robust.min(a) = std::max(box.min(a), low - margin);
    robust.max(a) = std::min(box.max(a), high + margin);
  }
  return robust;
}

}  // namespace sextant
