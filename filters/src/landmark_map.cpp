#include "sextant/filters/landmark_map.hpp"

#include <cassert>
#include <utility>

namespace sextant {
namespace {

/// B^level: the number of landmarks under one child of a node at `level` + 1.
int subtree_span(int level) {
  int s = 1;
  for (int k = 0; k < level; ++k) s *= kMapBranching;
  return s;
}

}  // namespace

const std::shared_ptr<const LandmarkEkf>& LandmarkMap::share(int i) const {
  assert(i >= 0 && i < size_);
  const Node* node = root_.get();
  for (int level = depth_ - 1; level > 0; --level)
    node = node->children[(i / subtree_span(level)) % kMapBranching].get();
  return node->leaves[i % kMapBranching];
}

// Path copying: a new node for every level on the way to `index`, each a copy of the old one
// (or empty where the path did not exist yet) with one child replaced. Old nodes are untouched,
// so every other map holding them keeps its landmarks.
std::shared_ptr<const LandmarkMap::Node> LandmarkMap::assign(const Node* node, int level, int index,
                                                             std::shared_ptr<const LandmarkEkf> leaf,
                                                             MapCounters* counters) {
  auto copy = node ? std::make_shared<Node>(*node) : std::make_shared<Node>();
  if (counters) ++counters->nodes_copied;
  const int slot = (index / subtree_span(level)) % kMapBranching;
  if (level == 0) {
    copy->leaves[slot] = std::move(leaf);
  } else {
    const Node* child = node ? node->children[slot].get() : nullptr;
    copy->children[slot] = assign(child, level - 1, index, std::move(leaf), counters);
  }
  return copy;
}

void LandmarkMap::set(int i, LandmarkEkf ekf, MapCounters* counters) {
  assert(i >= 0 && i < size_);
  if (counters) ++counters->landmarks_written;
  root_ = assign(root_.get(), depth_ - 1, i, std::make_shared<const LandmarkEkf>(std::move(ekf)), counters);
}

void LandmarkMap::push_back(LandmarkEkf ekf, MapCounters* counters) {
  if (size_ == subtree_span(depth_)) {  // full: the old root becomes the first child of a new root
    auto grown = std::make_shared<Node>();
    if (counters) ++counters->nodes_copied;
    grown->children[0] = root_;
    root_ = grown;
    ++depth_;
  }
  ++size_;
  set(size_ - 1, std::move(ekf), counters);
}

}  // namespace sextant
