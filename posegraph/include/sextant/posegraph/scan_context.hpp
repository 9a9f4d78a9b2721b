#pragma once
// Scan Context (Kim & Kim, IROS 2018): a global descriptor of one scan, computed from the scan
// alone, that recognises a revisited place however far the estimated trajectory has drifted
// (thesis §7.2: "an independent loop detection mechanism").
//
//   image: the sensor's surroundings in polar bins, `rings` rings of max_range / rings metres by
//     `sectors` sectors of 2π / sectors; a bin holds the highest point in it, z + height_offset
//     (0: empty, or nothing above −height_offset);
//   ring key: per ring, the mean of its bins. Invariant to the sensor's yaw, it finds the few
//     nearest earlier scans cheaply. (The paper's occupancy ratio, the fraction of non-empty bins,
//     is 1 on every ring that sees the ground, so it cannot tell places apart; the mean height is
//     what Kim & Kim's own code uses.)
//   distance: the image columns (one per sector) compared by cosine distance, averaged over the
//     columns non-empty in both, minimised over the column shifts n of the earlier image:
//       d(A, B) = min_n  mean_s (1 − a_{s+n}·b_s / (‖a_{s+n}‖‖b_s‖))
//     The shift that minimises it is the yaw of the later scan in the earlier one's frame,
//     n · 2π / sectors (one sector's resolution).
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"

namespace sextant {

struct ScanContextSettings {
  std::size_t rings = 20;                ///< N_r, radial bins
  std::size_t sectors = 60;              ///< N_s, angular bins (6° each)
  double max_range = 80.0;               ///< [m] points further away are left out
  double height_offset = 2.0;            ///< [m] added to z (the sensor's height above the ground)
  std::size_t ring_key_neighbours = 10;  ///< earlier scans compared by the full distance per query
  double max_distance = 0.2;             ///< a candidate when d ≤ this (0: identical, 1: unrelated)
  std::size_t min_index_gap = 30;        ///< earlier scans this close in the sequence are not places
  std::size_t stride = 4;                ///< scans between consecutive candidates' later scan at least

  bool valid(std::string* why) const;
};

struct ScanContext {
  Eigen::MatrixXf image;     ///< rings × sectors, max height + offset per bin (0: empty)
  Eigen::VectorXf ring_key;  ///< rings, mean bin value per ring
};

/// The descriptor of one scan (sensor frame: x forward, y left, z up).
ScanContext make_scan_context(const PointCloud& cloud, const ScanContextSettings& settings);

struct ScanContextMatch {
  double distance = 1.0;  ///< d(A, B) ∈ [0, 1]; 1 when no column is non-empty in both
  int shift = 0;          ///< n: B's sector s matches A's sector s + n
  double yaw = 0.0;       ///< [rad] n · 2π / sectors, in (−π, π]: B's yaw in A's frame
};

/// Compares `later` with `earlier` over every column shift.
ScanContextMatch compare_scan_contexts(const ScanContext& earlier, const ScanContext& later);

/// A revisit proposed by the descriptors alone.
struct PlaceMatch {
  std::size_t i = 0, j = 0;  ///< earlier, later scan (i + min_index_gap ≤ j)
  ScanContextMatch match;
  /// The relative pose the descriptor gives: T_i⁻¹·T_j ≈ Rz(yaw) (no translation: the descriptor
  /// does not measure it; the verifying registration's wide basin finds it).
  Eigen::Isometry3d guess() const;
};

/// For every later scan j (at least `stride` apart between matches): its ring key's nearest earlier
/// scans compared by the full distance, the closest kept when d ≤ max_distance. In increasing j.
std::vector<PlaceMatch> find_place_matches(const std::vector<ScanContext>& contexts,
                                           const ScanContextSettings& settings);

}  // namespace sextant
