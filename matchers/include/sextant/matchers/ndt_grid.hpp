#pragma once
// A dense grid of normal distributions (NDT cells, eqs. 3.2–3.3) and the ML-NDT layer pyramid
// (Table 3.1, §3.2). Cells are found by a dense index floor((p − origin) / edge), no hashing;
// the Gaussians (mean and C⁻¹) are stored contiguously for the score kernels.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sextant/core/point_cloud.hpp"
#include "sextant/matchers/registration_result.hpp"

namespace sextant {

struct CellStatsSettings {
  std::size_t min_points = 5;      ///< a cell gets a Gaussian with at least this many points (Table 3.1: > 4)
  double max_eigen_ratio = 100.0;  ///< eigenvalues below λmax / ratio are raised to it (text after eq. 3.11)
  /// Cells whose largest covariance eigenvalue is below this are dropped: repeated points give
  /// no surface, and their near-singular C⁻¹ would dominate eq. (3.11) [m²]
  double min_spread = 1e-6;
  /// Cells whose points spread less than this fraction of the cell edge (standard deviation along
  /// the widest axis) are dropped too: a blob, not a surface at this layer's resolution. Repeating
  /// every point with a little noise turns cells with one point into such blobs, whose sharp
  /// Gaussians then dominated eq. (3.11) in the untruncated coarse layers (issue 22). 0 keeps them
  /// (NDT, and ML-NDT's `thesis` preset); ML-NDT's default is 0.02 [fraction]
  double min_relative_spread = 0.0;
  bool valid(std::string* why) const;
};

namespace ndt_detail {
struct CellSums;  ///< running sums of one occupied cell (ndt_grid.cpp)
}
struct LayerPyramidSettings;

/// One cell's normal distribution in the hot-loop layout: mean and the upper triangle of C⁻¹.
struct CellGaussian {
  float mean[3];
  float inv_cov[6];  ///< xx xy xz yy yz zz of C⁻¹
};

class NdtGrid {
 public:
  NdtGrid() = default;

  /// Cubic cells of edge `cell_edge` [m]; `dims` cells per axis starting at `origin`.
  /// Reference points outside the box are ignored. A grid of more than `max_cells` cells (or 2³¹ − 1) is
  /// refused (empty grid, too_large() true) rather than exhausting memory.
  static NdtGrid build(const PointCloud& reference, const Eigen::Vector3d& origin, double cell_edge,
                       const Eigen::Vector3i& dims, const CellStatsSettings& settings = {},
                       std::size_t max_cells = std::size_t{1} << 27);
  /// Cells of edge `cell_edge` over the reference's bounding box, ceil(extent / edge) per axis.
  static NdtGrid build_over_bounds(const PointCloud& reference, double cell_edge,
                                   const CellStatsSettings& settings = {});

  bool empty() const { return gaussians_.empty(); }
  bool too_large() const { return too_large_; }
  double cell_edge() const { return cell_edge_; }
  const Eigen::Vector3d& origin() const { return origin_; }
  const Eigen::Vector3i& dims() const { return dims_; }
  std::size_t cell_count() const { return index_.size(); }
  std::size_t gaussian_count() const { return gaussians_.size(); }
  /// Reference points in the cells that got a Gaussian (the part of the reference this grid models).
  std::size_t modelled_points() const { return modelled_points_; }

  /// Index of the Gaussian of the cell containing p, or −1 (outside, or too few points).
  int lookup(float x, float y, float z) const {
    const float fx = (x - ox_) * inv_edge_, fy = (y - oy_) * inv_edge_, fz = (z - oz_) * inv_edge_;
    if (!(fx >= 0.f && fy >= 0.f && fz >= 0.f && fx < fdx_ && fy < fdy_ && fz < fdz_)) return -1;
    return index_[cell_index(static_cast<int>(fx), static_cast<int>(fy), static_cast<int>(fz))];
  }
  /// Gaussian index of cell (ix, iy, iz), or −1 when outside or empty.
  int at(int ix, int iy, int iz) const {
    if (ix < 0 || iy < 0 || iz < 0 || ix >= dims_.x() || iy >= dims_.y() || iz >= dims_.z()) return -1;
    return index_[cell_index(ix, iy, iz)];
  }
  const CellGaussian& gaussian(int g) const { return gaussians_[static_cast<std::size_t>(g)]; }
  const std::vector<CellGaussian>& gaussians() const { return gaussians_; }
  /// Inflated covariance C' of Gaussian g, the inverse of its stored C'⁻¹ (float precision; for
  /// tests and reports, computed on each call: the build keeps only the hot-loop layout).
  Eigen::Matrix3d covariance(int g) const;
  /// Upper-triangular Lᵀ with C'⁻¹ = L·Lᵀ (the Ceres residual Lᵀe), from the stored C'⁻¹; computed
  /// on each call.
  Eigen::Matrix3d sqrt_information(int g) const;
  /// Index of the cell holding Gaussian g along each axis.
  Eigen::Vector3i cell_of(int g) const;

 private:
  friend std::vector<NdtGrid> build_layer_pyramid(const PointCloud& reference,
                                                  const LayerPyramidSettings& settings, const Bounds& box,
                                                  NdtGrid* finer, const CellStatsSettings* finer_cells);
  /// Geometry and an empty index; false (an empty grid) for a bad geometry or too many cells.
  bool init(const Eigen::Vector3d& origin, double cell_edge, const Eigen::Vector3i& dims,
            std::size_t max_cells);
  /// Splitting process: the sums of every occupied cell (index_ holds their positions).
  std::vector<ndt_detail::CellSums> split(const PointCloud& reference);
  /// The sums of this grid's cells from those of a grid with half its edge and the same origin
  /// (cell (x, y, z) there lies in cell (x/2, y/2, z/2) here).
  std::vector<ndt_detail::CellSums> merge_children(const std::vector<ndt_detail::CellSums>& children);
  /// Generative process: a Gaussian for every cell of `sums` with enough points.
  void generate(const std::vector<ndt_detail::CellSums>& sums, const CellStatsSettings& settings);

  std::size_t cell_index(int ix, int iy, int iz) const {
    return (static_cast<std::size_t>(iz) * static_cast<std::size_t>(dims_.y()) +
            static_cast<std::size_t>(iy)) *
               static_cast<std::size_t>(dims_.x()) +
           static_cast<std::size_t>(ix);
  }
  /// (ix, iy, iz) of a cell_index().
  Eigen::Vector3i cell_coordinates(std::size_t cell) const;

  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  Eigen::Vector3i dims_ = Eigen::Vector3i::Zero();
  double cell_edge_ = 0.0;
  float ox_ = 0.f, oy_ = 0.f, oz_ = 0.f, inv_edge_ = 0.f, fdx_ = 0.f, fdy_ = 0.f, fdz_ = 0.f;
  bool too_large_ = false;
  std::size_t modelled_points_ = 0;
  std::vector<std::int32_t> index_;  ///< cell → Gaussian index or −1
  std::vector<CellGaussian> gaussians_;
  std::vector<std::int32_t> cell_of_gaussian_;
};

/// Geometry of ML-NDT layer i (§3.2): the bounding box is split into qⁱ cubes of equal volume,
/// edge k = (V / qⁱ)^(1/3), and ceil(extent / k) cells per axis. Axes of (near) zero extent are
/// left out of the volume (a planar cloud uses areas and square roots).
struct LayerGeometry {
  double cell_edge = 0.0;                          ///< k [m]
  Eigen::Vector3i dims = Eigen::Vector3i::Zero();  ///< cells per axis
};
LayerGeometry layer_geometry(const Bounds& bounds, int q, int layer);

/// The box the pyramid is built over: per axis, the `quantile` and 1 − `quantile` quantiles of the
/// points (of an evenly strided subsample of at most 16,384 points), widened by 10 % of that extent
/// on each side and clipped to the bounding box. One stray return 10 km away, or every point
/// repeated, leaves it (and so the cell sizes) where it was; quantile 0 is the bounding box (§3.2).
Bounds robust_bounds(const PointCloud& cloud, double quantile);

struct LayerPyramidSettings {
  int division = 8;  ///< q: layer i splits the bounding volume into qⁱ cells
  int layers = 4;    ///< n: layers 1..n
  /// The box split into the layers (robust_bounds): 0 = the bounding box, as the thesis does (the
  /// `thesis` preset); the default leaves out the farthest 0.5 % along each axis, so that a layer's
  /// cell size does not hang on one far point [fraction, 0..0.25)
  double bounds_quantile = 0.005;
  CellStatsSettings cells;
  bool valid(std::string* why) const;
};

/// Why a reference model has nothing to match against: kEmptyInput (no reference points),
/// kGridTooLarge (the cells would be too many) or kNoGaussians (no cell with enough spread points:
/// cells too small for the point density, or every cell flat to a blob).
Termination empty_model_reason(std::size_t reference_points, const NdtGrid& grid);

/// Layers 1..n of Table 3.1 ("splitting" and "generative" processes) over robust_bounds(reference,
/// settings.bounds_quantile) (points outside it are not in any cell); element 0 is layer 1. With
/// q = 8 over a volume the cells nest (the edge halves): the points are split once into layer n
/// and every coarser layer sums its 2 × 2 × 2 children, with edges exactly 2^(n−i) × layer n's
/// (layer_geometry's to rounding). Otherwise every layer is split from the points.
std::vector<NdtGrid> build_layer_pyramid(const PointCloud& reference, const LayerPyramidSettings& settings);
/// The same over `box`, robust_bounds(reference, settings.bounds_quantile) computed by the caller.
/// With `finer`, and when the layers nest, the split is into layer n + 1 instead (edge half of layer
/// n's, the same origin, twice its cells per axis), which `finer` receives, and layer n sums its
/// children there: ML-NDT's aligned precision grid (precision_stage.hpp) from the pyramid's one pass
/// over the points; its Gaussians follow `finer_cells` (default: the layers' own settings.cells).
/// `finer` is left empty when the layers do not nest (pyramid_nests is false) or it would have too
/// many cells.
std::vector<NdtGrid> build_layer_pyramid(const PointCloud& reference, const LayerPyramidSettings& settings,
                                         const Bounds& box, NdtGrid* finer = nullptr,
                                         const CellStatsSettings* finer_cells = nullptr);
/// Whether the layers over `box` nest (q = 8 and each layer's edge twice the next one's; see
/// build_layer_pyramid), so that build_layer_pyramid can also give layer n + 1.
bool pyramid_nests(const Bounds& box, const LayerPyramidSettings& settings);

}  // namespace sextant
