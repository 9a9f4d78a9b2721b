#pragma once
// Plane-feature extraction (§3.3.1, §4.1): fixed cells → RANSAC per cell → refit (PCA or SVD)
// → hull → merging → ground removal → landmark acceptance.
//
//   PlaneExtractionSettings s;                // or read_plane_extraction_settings (features/yaml.hpp)
//   Rng rng(seed);
//   PlaneExtraction out = extract_planes(cloud, s, rng);
//   for (const PlaneLandmark& l : out.landmarks) ...
#include <cstddef>
#include <string>
#include <vector>

#include "sextant/core/point_cloud.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/features/landmark.hpp"
#include "sextant/features/merging.hpp"

namespace sextant {

struct PlaneExtractionSettings {
  double cell_size = 2.0;                 ///< edge of the cubic extraction cells [m, ≤ 1000]
  double distance_threshold = 0.05;       ///< RANSAC inlier distance to the plane [m, ≤ cell_size]
  int ransac_iterations = 100;            ///< maximum RANSAC hypotheses per plane [count]
  double ransac_confidence = 0.99;        ///< stop early once this confidence is reached [0, 1)
  std::size_t min_inliers = 10;           ///< a cell plane needs at least this many inliers (thesis: 10)
  double min_inlier_ratio = 0.5;          ///< … and this share of the cell's remaining points [0, 1]
  int max_planes_per_cell = 2;            ///< planes searched per cell (corners hold two) [count ≥ 1]
  std::string refit = "pca";              ///< "pca" or "svd" (eqs. (3.23)–(3.25))
  bool merge = true;                      ///< run the merging step of §4.1
  MergeThresholds merge_thresholds;       ///< t_o, t_t, t_p (YAML: map `merge_thresholds`)
  bool remove_horizontal = true;          ///< drop ground/roof planes
  double horizontal_max_tilt_deg = 20.0;  ///< normal within this angle of up (z) → horizontal [deg]
  double min_landmark_area = 1.0;         ///< landmark needs this hull area [m²]
  std::size_t min_landmark_inliers = 30;  ///< … and this many inliers [count]
  /// The cells: 0 = cubes of cell_size anchored at the origin; i ≥ 1 = the cells of layer i of the
  /// cloud's own ML-NDT split (Table 3.2, feature extraction: Split(S, q, n)): its bounding box cut
  /// into qⁱ cubes of edge (V / qⁱ)^(1/3) (§3.2), anchored at the box's low corner [layer, 0..8]
  int split_layer = 0;
  int split_division = 8;  ///< q of that split [count ≥ 2]
  /// true: a cell plane's inliers are those of its refit (two passes); false: they are RANSAC's
  /// (§3.3.1.1: the fit only gives the plane's parameters), as the thesis' feature sample has them
  bool refit_inliers = true;
  bool valid(std::string* why) const;
};

/// The feature sample of the thesis' FbML-NDT (§3.3.1.1, §3.3.1.3, Table 3.2): RANSAC in each cell of
/// the input's own split at layer n = 4 (q = 8), one plane per cell, kept when its inliers exceed 10
/// ("practically 10"; no share of the cell asked), F = RANSAC's inliers. The thesis leaves the inlier
/// distance open (kept at 5 cm). YAML `preset: thesis` in the settings of `fbs` and of fbmlndt's
/// `features:`.
PlaneExtractionSettings thesis_feature_sampling();

struct ExtractionStatistics {
  std::size_t points = 0;                   ///< finite input points
  std::size_t non_finite_points = 0;        ///< skipped NaN/Inf points
  std::size_t cells = 0;                    ///< occupied cells
  std::size_t cells_too_few_points = 0;     ///< fewer than min_inliers points
  std::size_t cells_duplicated_points = 0;  ///< fewer than min_inliers distinct points
  std::size_t cells_collinear = 0;          ///< points on a line (second principal spread ≤ threshold)
  std::size_t cells_without_plane = 0;      ///< RANSAC found no acceptable plane
  std::size_t cell_planes = 0;              ///< planes found in cells (before merging)
  std::size_t merged_planes = 0;            ///< planes after merging
  std::size_t horizontal_removed = 0;       ///< merged planes dropped as horizontal
  std::size_t too_small_removed = 0;        ///< merged planes below the area / inlier thresholds
  std::size_t landmarks = 0;
  double cell_edge = 0.0;  ///< edge of the extraction cells used (cell_size, or split_layer's) [m]
  double seconds = 0.0;    ///< wall time of extract_planes [s]
};

struct PlaneExtraction {
  std::vector<PlaneLandmark> landmarks;    ///< accepted merged planes (inlier indices into the input)
  std::vector<PlaneLandmark> cell_planes;  ///< per-cell planes before merging
  ExtractionStatistics stats;
  /// Ascending, unique indices of all cell-plane inliers (the `fbs` sample, Table 3.2).
  std::vector<std::size_t> cell_inlier_indices() const;
};

/// Never throws for bad data: NaN points are skipped and counted; invalid settings throw
/// std::invalid_argument (check valid() first).
PlaneExtraction extract_planes(const PointCloud& cloud, const PlaneExtractionSettings& settings, Rng& rng);

/// Only the per-cell RANSAC stage (what FbML-NDT needs, Table 3.2): cell planes and statistics.
PlaneExtraction extract_cell_planes(const PointCloud& cloud, const PlaneExtractionSettings& settings,
                                    Rng& rng);

}  // namespace sextant
