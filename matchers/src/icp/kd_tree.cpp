#include "icp/kd_tree.hpp"

#include <algorithm>
#include <cmath>

namespace sextant {

namespace {

float squared_distance(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  return (a - b).squaredNorm();
}

}  // namespace

/// A bounded max-heap of the k best neighbours found so far, kept as a sorted array (k is small).
class KdTree::KnnHeap {
 public:
  KnnHeap(std::size_t k, float max_squared_distance, std::vector<Neighbour>& out)
      : k_(k), max_squared_distance_(max_squared_distance), out_(out) {
    out_.clear();
    out_.reserve(k);
  }
  /// Squared radius a candidate must beat.
  float bound() const { return out_.size() < k_ ? max_squared_distance_ : out_.back().squared_distance; }
  void offer(std::size_t index, float d2) {
    if (d2 > bound() || (out_.size() == k_ && d2 == bound())) return;
    if (out_.size() == k_) out_.pop_back();
    const auto at = std::upper_bound(out_.begin(), out_.end(), d2,
                                     [](float d, const Neighbour& n) { return d < n.squared_distance; });
    out_.insert(at, Neighbour{index, d2});
  }

 private:
  std::size_t k_;
  float max_squared_distance_;
  std::vector<Neighbour>& out_;
};

void KdTree::build(PointsView points, int leaf_size) {
  nodes_.clear();
  points_.clear();
  original_.clear();
  leaf_size = std::max(leaf_size, 1);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].allFinite()) {
      points_.push_back(points[i]);
      original_.push_back(static_cast<std::uint32_t>(i));
    }
  }
  if (points_.empty()) return;
  std::vector<std::uint32_t> order(points_.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  nodes_.reserve(2 * points_.size() / static_cast<std::size_t>(leaf_size) + 1);
  build_node(0, static_cast<std::uint32_t>(points_.size()), leaf_size, order);

  // Store the points contiguously in tree order so a leaf scan walks consecutive memory.
  std::vector<Eigen::Vector3f> sorted(points_.size());
  std::vector<std::uint32_t> sorted_original(points_.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    sorted[i] = points_[order[i]];
    sorted_original[i] = original_[order[i]];
  }
  points_.swap(sorted);
  original_.swap(sorted_original);
}

// Splits at the median of the widest axis: left holds coordinates ≤ split, right ≥ split.
std::uint32_t KdTree::build_node(std::uint32_t begin, std::uint32_t end, int leaf_size,
                                 std::vector<std::uint32_t>& order) {
  const auto id = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  if (end - begin <= static_cast<std::uint32_t>(leaf_size)) {
    nodes_[id].begin = begin;
    nodes_[id].end = end;
    return id;
  }
  Eigen::Vector3f lo = points_[order[begin]], hi = lo;
  for (std::uint32_t i = begin + 1; i < end; ++i) {
    lo = lo.cwiseMin(points_[order[i]]);
    hi = hi.cwiseMax(points_[order[i]]);
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) { return points_[a][axis] < points_[b][axis]; });
  const float split = points_[order[mid]][axis];
  const std::uint32_t left = build_node(begin, mid, leaf_size, order);
  const std::uint32_t right = build_node(mid, end, leaf_size, order);
  Node& node = nodes_[id];
  node.axis = axis;
  node.split = split;
  node.left = left;
  node.right = right;
  return id;
}

bool KdTree::nearest(const Eigen::Vector3f& query, float max_squared_distance, Neighbour* out) const {
  if (nodes_.empty() || !query.allFinite() || !(max_squared_distance >= 0.0f)) return false;
  Neighbour best{original_.size(), max_squared_distance};
  search_nearest(0, query, best);
  if (best.index == original_.size()) return false;
  out->index = original_[best.index];
  out->squared_distance = best.squared_distance;
  return true;
}

void KdTree::search_nearest(std::uint32_t node_id, const Eigen::Vector3f& q, Neighbour& best) const {
  const Node& node = nodes_[node_id];
  if (node.axis < 0) {
    for (std::uint32_t i = node.begin; i < node.end; ++i) {
      const float d2 = squared_distance(points_[i], q);
      if (d2 <= best.squared_distance) {
        best.squared_distance = d2;
        best.index = i;
      }
    }
    return;
  }
  const float diff = q[node.axis] - node.split;
  const std::uint32_t near = diff < 0.0f ? node.left : node.right;
  const std::uint32_t far = diff < 0.0f ? node.right : node.left;
  search_nearest(near, q, best);
  if (diff * diff <= best.squared_distance) search_nearest(far, q, best);
}

void KdTree::k_nearest(const Eigen::Vector3f& query, std::size_t k, std::vector<Neighbour>& out,
                       float max_squared_distance) const {
  KnnHeap heap(k, max_squared_distance, out);
  if (nodes_.empty() || k == 0 || !query.allFinite() || !(max_squared_distance >= 0.0f)) return;
  search_k_nearest(0, query, heap);
  for (Neighbour& n : out) n.index = original_[n.index];
}

void KdTree::search_k_nearest(std::uint32_t node_id, const Eigen::Vector3f& q, KnnHeap& heap) const {
  const Node& node = nodes_[node_id];
  if (node.axis < 0) {
    for (std::uint32_t i = node.begin; i < node.end; ++i) heap.offer(i, squared_distance(points_[i], q));
    return;
  }
  const float diff = q[node.axis] - node.split;
  const std::uint32_t near = diff < 0.0f ? node.left : node.right;
  const std::uint32_t far = diff < 0.0f ? node.right : node.left;
  search_k_nearest(near, q, heap);
  if (diff * diff <= heap.bound()) search_k_nearest(far, q, heap);
}

}  // namespace sextant
