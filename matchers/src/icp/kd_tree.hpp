#pragma once
// A static k-d tree over float xyz points for the ICP baselines: built once from a reference
// cloud, then queried for the nearest neighbour (correspondences) and the k nearest neighbours
// (normals by PCA). Points are copied into a contiguous buffer in tree order; leaves hold small
// buckets that are scanned linearly. Non-finite points are left out at build time.
//
//   KdTree tree(reference.points());
//   KdTree::Neighbour n;
//   if (tree.nearest(q, max_distance * max_distance, &n)) use(reference[n.index]);
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "sextant/core/point_cloud.hpp"

namespace sextant {

class KdTree {
 public:
  struct Neighbour {
    std::size_t index = 0;          ///< index into the points given to build()
    float squared_distance = 0.0f;  ///< [m²]
  };

  KdTree() = default;
  explicit KdTree(PointsView points, int leaf_size = 8) { build(points, leaf_size); }

  /// Rebuilds the tree; non-finite points are skipped (indices still refer to `points`).
  void build(PointsView points, int leaf_size = 8);

  /// Number of (finite) points in the tree.
  std::size_t size() const { return points_.size(); }
  bool empty() const { return points_.empty(); }

  /// The nearest point with squared distance ≤ `max_squared_distance`; false when there is none
  /// (or the query is not finite).
  bool nearest(const Eigen::Vector3f& query, float max_squared_distance, Neighbour* out) const;
  bool nearest(const Eigen::Vector3f& query, Neighbour* out) const {
    return nearest(query, std::numeric_limits<float>::infinity(), out);
  }

  /// Up to `k` nearest points with squared distance ≤ `max_squared_distance`, ascending by
  /// distance, written into `out` (cleared first).
  void k_nearest(const Eigen::Vector3f& query, std::size_t k, std::vector<Neighbour>& out,
                 float max_squared_distance = std::numeric_limits<float>::infinity()) const;

 private:
  struct Node {
    float split = 0.0f;
    std::int32_t axis = -1;             ///< −1 for a leaf
    std::uint32_t begin = 0, end = 0;   ///< leaf: point range in points_
    std::uint32_t left = 0, right = 0;  ///< inner node: child node indices
  };
  class KnnHeap;

  std::uint32_t build_node(std::uint32_t begin, std::uint32_t end, int leaf_size,
                           std::vector<std::uint32_t>& order);
  void search_nearest(std::uint32_t node, const Eigen::Vector3f& q, Neighbour& best) const;
  void search_k_nearest(std::uint32_t node, const Eigen::Vector3f& q, KnnHeap& heap) const;

  std::vector<Node> nodes_;
  std::vector<Eigen::Vector3f> points_;  ///< in tree order
  std::vector<std::uint32_t> original_;  ///< tree order → index given to build()
};

}  // namespace sextant
