#pragma once
// Merging of plane segments (§4.1): orientation C_o, translation C_t and closeness C_p tests
// with the pooled covariance of eq. (4.53); region growing until no pair passes; and the merge
// of semantic data (centroid, covariance, hull, area) used by SLAM after an update.
#include <string>
#include <vector>

#include "sextant/features/landmark.hpp"

namespace sextant {

struct MergeThresholds {
  double orientation_deg = 15.0;  ///< t_o on C_o [deg]
  double translation = 0.75;      ///< t_t on C_t [m]
  double closeness = 10.0;        ///< t_p on C_p (Mahalanobis distance) [1]
  double min_variance = 1e-4;     ///< added to the diagonal of Σ_p so thin planes stay invertible [m²]
  bool valid(std::string* why) const;
};

/// The three test values plus the Euclidean centre distance (Table 4.1's columns).
struct MergeCriteria {
  double orientation_deg = 0.0;  ///< C_o = |acos(nᵢ·nⱼ)| [deg]
  double translation = 0.0;      ///< C_t = |n·(cᵢ − cⱼ)|, n of the plane with more inliers [m]
  double closeness = 0.0;  ///< C_p = sqrt((cᵢ−cⱼ)ᵀ Σ_p⁻¹ (cᵢ−cⱼ)), Σ_p of eq. (4.53) [1]
  double centre_distance = 0.0;  ///< d_c = |cᵢ − cⱼ| [m]
  bool passes(const MergeThresholds& t) const {
    return orientation_deg < t.orientation_deg && translation < t.translation && closeness < t.closeness;
  }
};

/// C_p is reported as the Mahalanobis *distance* (square root of the printed quadratic form):
/// Table 4.1's magnitudes and t_p = 10 match the distance, and with the square two adjacent cells
/// of one wall (C_p² = 12 along the row) could never merge.
MergeCriteria merge_criteria(const PlaneLandmark& a, const PlaneLandmark& b, double min_variance = 1e-4);

/// Evaluates the tests cheapest first and stops at the first failure (`out` then holds the
/// values computed so far). Returns true when all three pass.
bool merge_test(const PlaneLandmark& a, const PlaneLandmark& b, const MergeThresholds& t,
                MergeCriteria* out = nullptr);

/// The union of two landmarks' semantic data: combined moments (centroid, covariance, count),
/// plane refit by PCA of the combined covariance with the normal on `a`'s side, hull of both
/// hulls projected onto the new plane, area from that hull, inlier indices concatenated.
PlaneLandmark merge_landmarks(const PlaneLandmark& a, const PlaneLandmark& b);

/// After a filter update: `map_landmark` absorbs the semantics of `observed_in_world` (already in
/// the world frame). Centroid, covariance, count, hull and area are merged; the plane (n, d) is
/// kept from the map landmark (the filter owns it), and the hull is projected onto that plane.
PlaneLandmark merge_landmark_semantics(const PlaneLandmark& map_landmark,
                                       const PlaneLandmark& observed_in_world);

struct MergeResult {
  std::vector<PlaneLandmark> planes;              ///< merged planes, largest first
  std::vector<std::vector<std::size_t>> members;  ///< input indices merged into each plane
  std::size_t merges = 0;                         ///< pairwise merges performed
  std::size_t tests = 0;                          ///< pairwise tests evaluated
};

/// Region growing (§4.1): seeds in decreasing inlier count absorb every plane that passes the
/// three tests against the grown plane (refit after each absorption) until none passes; then
/// the grown planes are merged among themselves the same way until no pair passes.
MergeResult merge_planes(const std::vector<PlaneLandmark>& planes, const MergeThresholds& thresholds);

}  // namespace sextant
