// The nearest-neighbour spacing of a scan (point_spacing.hpp), over the ICP baselines' k-d tree.
#include "sextant/matchers/point_spacing.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "icp/kd_tree.hpp"

namespace sextant {

PointSpacing measure_point_spacing(const PointCloud& scan, std::size_t max_queries) {
  PointSpacing out;
  std::vector<std::size_t> finite;
  finite.reserve(scan.size());
  for (std::size_t i = 0; i < scan.size(); ++i)
    if (scan[i].allFinite()) finite.push_back(i);
  out.finite = finite.size();
  if (finite.size() < 2 || max_queries == 0) return out;
  const KdTree tree(scan.points());
  const std::size_t step = std::max<std::size_t>(1, (finite.size() + max_queries - 1) / max_queries);
  std::vector<double> distances;
  distances.reserve(finite.size() / step + 1);
  std::vector<KdTree::Neighbour> two;
  for (std::size_t k = 0; k < finite.size(); k += step) {
    tree.k_nearest(scan[finite[k]], 2, two);  // itself, and its nearest other point
    if (two.size() < 2) continue;
    const KdTree::Neighbour& other = two[0].index == finite[k] ? two[1] : two[0];
    distances.push_back(std::sqrt(static_cast<double>(other.squared_distance)));
  }
  out.queried = distances.size();
  if (distances.empty()) return out;
  const auto mid = distances.begin() + static_cast<std::ptrdiff_t>(distances.size() / 2);
  std::nth_element(distances.begin(), mid, distances.end());
  out.median = *mid;
  return out;
}

}  // namespace sextant
