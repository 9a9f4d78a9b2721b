#pragma once
// The per-particle landmark map of FastSLAM (fastslam.hpp): one small EKF (mean, covariance) per
// landmark, stored copy-on-write so that particles share every landmark they have not changed.
//
// Layout: a persistent k-ary trie (kMapBranching children per node) indexed by the landmark
// index, with immutable nodes held by shared_ptr — the log-N landmark tree of Montemerlo et al.
// (FastSLAM, AAAI 2002, its "efficient implementation" section), with a branching factor above 2 so the
// tree is shallow. Costs, for M landmarks and depth D = ⌈log_B M⌉:
//   copy of a map (a resampled particle)  O(1): one root pointer, no node or landmark copied;
//   get(i)                                O(D);
//   set(i, ekf) / push_back(ekf)          O(D·B): the path from the root to i is copied, every
//                                         other node stays shared with the maps it came from.
// A set() never changes what another map sees (copy-on-write), since nodes are never mutated.
#include <array>
#include <cstddef>
#include <memory>

#include <Eigen/Core>

namespace sextant {

/// What a caller keeps per landmark beside its EKF, per particle (plane SLAM: the plane's semantic
/// data — centroid, hull, area — in that particle's world, plane_particle_association.hpp).
/// Immutable and shared like the EKFs: a particle that changes it stores a new one.
struct LandmarkAttachment {
  virtual ~LandmarkAttachment() = default;
};

/// One landmark's EKF in a particle: its mean and covariance in the SlamModel's landmark
/// parameterisation (planes: (nᵂ, dᵂ), plane_slam_model.hpp), and the caller's attachment.
struct LandmarkEkf {
  Eigen::VectorXd mean;
  Eigen::MatrixXd covariance;
  std::shared_ptr<const LandmarkAttachment> attachment = nullptr;  ///< null unless a caller set one
};

/// What map writes cost: new landmark EKFs stored and trie nodes created (path copies).
/// Copying a map (resampling) adds to neither.
struct MapCounters {
  std::size_t landmarks_written = 0;  ///< LandmarkEkf objects created by set()/push_back()
  std::size_t nodes_copied = 0;       ///< trie nodes created (copied or new) by set()/push_back()
};

inline constexpr int kMapBranching = 8;

class LandmarkMap {
 public:
  int size() const { return size_; }
  /// Landmark i's EKF (0 ≤ i < size(); checked by assertion only: the filter checks indices).
  const LandmarkEkf& get(int i) const { return *share(i); }
  /// The shared landmark object itself (identity tells whether two maps share it).
  const std::shared_ptr<const LandmarkEkf>& share(int i) const;
  /// Replaces landmark i: copies the path from the root to i, O(log M).
  void set(int i, LandmarkEkf ekf, MapCounters* counters = nullptr);
  /// Appends a landmark with index size(), O(log M).
  void push_back(LandmarkEkf ekf, MapCounters* counters = nullptr);
  /// Trie depth (levels of nodes; 1 while size() ≤ kMapBranching).
  int depth() const { return depth_; }

 private:
  struct Node {
    std::array<std::shared_ptr<const Node>, kMapBranching> children;       // inner nodes
    std::array<std::shared_ptr<const LandmarkEkf>, kMapBranching> leaves;  // level-0 nodes
  };
  static std::shared_ptr<const Node> assign(const Node* node, int level, int index,
                                            std::shared_ptr<const LandmarkEkf> leaf, MapCounters* counters);

  std::shared_ptr<const Node> root_;
  int depth_ = 1;
  int size_ = 0;
};

}  // namespace sextant
