#pragma once
// ML-NDT's precision stage (issue 22). The pyramid's cells are fractions of the reference's box
// (§3.2, Table 3.1: layer i splits it into qⁱ cubes), so a pose is only as precise as the last
// layer's cells resolve the scene: on a large outdoor scan they are metres wide, and each holds
// several surfaces in one blurred Gaussian (docs/matcher_defaults.md, "Precision stage"). More
// layers from the start layer do not help: the finer layers then run from the coarse layers' early
// poses, and their narrow basins pull a right pose away (the thesis' E4 guideline).
//
// The precision stage continues after the pyramid has chosen its pose (after refine_first and the
// wide basin too), from that pose only, so that the coarse layers' reach is kept and a finer grid's
// narrower basin never sees a bad guess. It registers once more against two overlapping grids
// (Biber and Straßer's overlapping NDT grids, reduced to one diagonal shift): one on the pyramid's
// origin and one shifted by half a cell along every axis, their truncated scores of eq. (3.11)
// summed. A single grid's score jumps where a point crosses a cell boundary (its Gaussian changes);
// with the shifted copy no boundary of one grid is a boundary of the other, so the pose is no longer
// pulled towards positions that keep points inside their cells.
//
// The edge is that of layer n + 1 (half the last layer's), but never below `min_cell`, a metric floor,
// and only when the finer cells still model the scene: when the aligned grid's Gaussians hold less than
// `min_coverage` of the reference points the last layer's Gaussians hold (too fine for the point
// density: a sparse or voxel-downsampled scan), the grids take the last layer's own edge instead.
// Overlap and fit (the trust checks) stay those of the last layer at the final pose; the Hessian is
// the precision stage's, whose minimum the pose is. A stage that does not converge leaves the
// pyramid's result as it was.
//
// The precision grids raise small eigenvalues only to λmax / 10⁴, where the pyramid raises them to
// λmax / 100 (the thesis' inflation after eq. 3.11, from Magnusson). The inflation keeps C invertible
// and widens the basin the coarse layers need; but it also thickens every planar cell to a tenth of
// its extent, so that the pattern of the returns inside a plane (rings that move with the sensor)
// pulls the pose as much as the plane's offset does. From a pose the pyramid has already found, the
// precision stage needs no basin: with thin Gaussians it fits the surfaces themselves, not the returns'
// pattern, whose pull biases every step's scale alike (docs/matcher_defaults.md, "Thin Gaussians in
// the precision stage").
//
// YAML keys of mlndt / fbmlndt: precision_min_cell (0 = off, the `thesis` preset), precision_min_coverage,
// precision_max_eigen_ratio, precision_spacing_cells.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sextant/core/point_cloud.hpp"
#include "sextant/matchers/ndt_grid.hpp"

namespace sextant {

struct PrecisionSettings {
  /// The smallest cell edge of the precision grids (their edge is max(this, half the last layer's),
  /// at most the last layer's). 1 m: a lidar surface patch of 1 m holds enough returns at the ranges
  /// that dominate a scan (beam spacing 0.2–0.5 m at 20–50 m) for a covariance, and the GBS input
  /// sample (1 m cells) has about one cluster per cell. 0 turns the stage off [m, 0 or [0.05, 100]]
  double min_cell = 1.0;
  /// The finer edge is used only when its cells with a Gaussian hold at least this fraction of the
  /// reference points the last layer's Gaussians hold; below it the grids take the last layer's edge
  /// [fraction, (0, 1]]
  double min_coverage = 0.8;
  /// The precision grids' max_eigen_ratio (CellStatsSettings): eigenvalues below λmax / ratio are
  /// raised to it. Far above the pyramid's 100: thin Gaussians for a pose already found; 10⁴ keeps
  /// C'⁻¹ well within float precision [ratio, ≥ 1]
  double max_eigen_ratio = 1e4;
  /// When positive, the floor `min_cell` is raised to this many times the reference's measured point
  /// spacing (measure_point_spacing): a cell of edge k·s holds about k² returns of a surface sampled s
  /// apart. Off by default: measured, not adopted (docs/matcher_defaults.md, "Precision cells from the
  /// point spacing") [count, 0 = off or [1, 1000]]
  double spacing_cells = 0.0;
  bool enabled() const { return min_cell > 0.0; }
  /// The precision grids' cell settings: the pyramid's `cells`, with this max_eigen_ratio.
  CellStatsSettings cells(const CellStatsSettings& pyramid_cells) const;
  bool valid(std::string* why) const;
};

/// Where the precision grids lie: layer n's origin, edge and cells (build_layer_pyramid's last layer).
struct PrecisionFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double last_edge = 0.0;
  Eigen::Vector3i last_dims = Eigen::Vector3i::Zero();
};

/// The edges to try, finest first: layer n + 1's (half the last layer's) but never below
/// `min_cell`, then the last layer's own; just the last layer's when the floor is above half of it;
/// none when the stage is off.
std::vector<double> precision_edges(double last_edge, const PrecisionSettings& settings);

/// One precision grid of edge `edge` over the frame's box, its origin moved by `shift`·edge along
/// every axis (0: aligned, 0.5: the shifted copy, one cell more per axis to cover the box). The aligned
/// grid of half the last layer's edge is layer n + 1 itself, which build_layer_pyramid gives from the
/// pyramid's own split when the layers nest (MlndtMatcher::set_reference).
NdtGrid precision_grid(const PointCloud& reference, const PrecisionFrame& frame, double edge, double shift,
                       const CellStatsSettings& cells);

/// Whether an (aligned, shifted) pair of one edge serves (MlndtMatcher::set_reference takes the first
/// edge whose pair does, and builds the first pair beside the pyramid): both hold Gaussians, and the aligned
/// one's model at least `min_coverage` of the reference points the last layer's Gaussians model.
bool precision_pair_usable(const NdtGrid& aligned, const NdtGrid& shifted, const NdtGrid& last_layer,
                           const PrecisionSettings& settings);

}  // namespace sextant
