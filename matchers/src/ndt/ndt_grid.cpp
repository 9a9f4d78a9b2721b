// Dense NDT cell grids (eqs. 3.2–3.3 with the covariance inflation after eq. 3.11) and the
// ML-NDT layer pyramid of Table 3.1.
#include "sextant/matchers/ndt_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "ndt/cell_covariance_lanes.hpp"
#include "ndt/cell_split.hpp"

namespace sextant {

namespace {

// A cell count from its real-valued ceiling: at least 1, saturated at INT_MAX (init() refuses such
// a grid) and defined for NaN (a cloud with non-finite bounds), which a plain cast to int is not.
int saturated_cell_count(double n) {
  if (!(n >= 1.0)) return 1;
  if (n >= static_cast<double>(std::numeric_limits<int>::max())) return std::numeric_limits<int>::max();
  return static_cast<int>(n);
}

using ndt_detail::CellSums;

/// Mean (eq. 3.2) and covariance (eq. 3.3, its upper triangle xx xy xz yy yz zz) of a cell, the mean
/// relative to the grid origin.
void cell_moments(const CellSums& s, double mean[3], double covariance[6]) {
  const double n = s.count;
  for (int i = 0; i < 3; ++i) mean[i] = s.sum[i] / n;
  const int row[6] = {0, 0, 0, 1, 1, 2}, col[6] = {0, 1, 2, 1, 2, 2};
  for (int e = 0; e < 6; ++e) covariance[e] = (s.sum_sq[e] - n * mean[row[e]] * mean[col[e]]) / (n - 1.0);
}

/// The stored C'⁻¹ of a cell as a symmetric double matrix.
Eigen::Matrix3d information_of(const CellGaussian& g) {
  const float* u = g.inv_cov;
  Eigen::Matrix3d inv;
  inv << u[0], u[1], u[2], u[1], u[3], u[4], u[2], u[4], u[5];
  return inv;
}

}  // namespace

bool CellStatsSettings::valid(std::string* why) const {
  const char* problem = nullptr;
  if (min_points < 4)
    problem = "min_points must be at least 4 (a 3D covariance needs more than 3 points)";
  else if (!(max_eigen_ratio >= 1.0))
    problem = "max_eigen_ratio must be at least 1";
  else if (!(min_spread >= 0.0) || !std::isfinite(min_spread))
    problem = "min_spread must be a variance ≥ 0 [m²]";
  else if (!(min_relative_spread >= 0.0 && min_relative_spread < 1.0))
    problem = "min_relative_spread must lie in [0, 1) (a fraction of the cell edge)";
  if (problem && why) *why = problem;
  return problem == nullptr;
}

bool NdtGrid::init(const Eigen::Vector3d& origin, double cell_edge, const Eigen::Vector3i& dims,
                   std::size_t max_cells) {
  origin_ = origin;
  cell_edge_ = cell_edge;
  if (!(cell_edge > 0.0) || !std::isfinite(cell_edge) || (dims.array() < 1).any() || !origin.allFinite())
    return false;
  // Cell indices are 32-bit (CellSums::cell, split's staging, cell_coordinates): never more than
  // 2³¹ − 1 cells, whatever max_cells says.
  constexpr double kIndexLimit = 2147483647.0;
  const double cells = static_cast<double>(dims.x()) * dims.y() * dims.z();
  if (cells > std::min(static_cast<double>(max_cells), kIndexLimit)) {
    too_large_ = true;
    return false;
  }
  dims_ = dims;
  ox_ = static_cast<float>(origin.x());
  oy_ = static_cast<float>(origin.y());
  oz_ = static_cast<float>(origin.z());
  inv_edge_ = static_cast<float>(1.0 / cell_edge);
  fdx_ = static_cast<float>(dims.x());
  fdy_ = static_cast<float>(dims.y());
  fdz_ = static_cast<float>(dims.z());
  index_.assign(static_cast<std::size_t>(cells), -1);
  return true;
}

std::vector<CellSums> NdtGrid::split(const PointCloud& reference) {
  const ndt_detail::SplitGrid grid{origin_.x(), origin_.y(), origin_.z(), 1.0 / cell_edge_,
                                   dims_.x(),   dims_.y(),   dims_.z()};
  const PointsView points = reference.points();
  // Every point's cell first, so that the accumulation can prefetch the cells of points ahead.
  const std::unique_ptr<std::uint32_t[]> cells(new std::uint32_t[points.size()]);  // each written, not zeroed
  ndt_detail::assign_cells(points, grid, cells.get());
  return ndt_detail::accumulate_cells(points, cells.get(), grid, index_.data());
}

std::vector<CellSums> NdtGrid::merge_children(const std::vector<CellSums>& children) {
  // The sums of eqs. (3.2)–(3.3) are additive over the children; children come in order of their
  // first point, so the cells here keep the order of their first point too.
  std::vector<CellSums> sums;
  sums.reserve(children.size());
  for (const CellSums& child : children) {
    const int x = child.x >> 1, y = child.y >> 1, z = child.z >> 1;
    const std::size_t cell = cell_index(x, y, z);
    std::int32_t& slot = index_[cell];
    if (slot < 0) {  // a new parent: its first child's sums (0 + a = a)
      slot = static_cast<std::int32_t>(sums.size());
      CellSums& parent = sums.emplace_back(child);
      parent.cell = static_cast<std::int32_t>(cell);
      parent.x = x, parent.y = y, parent.z = z;
      continue;
    }
    CellSums& s = sums[static_cast<std::size_t>(slot)];
    s.count += child.count;
    for (int i = 0; i < 3; ++i) s.sum[i] += child.sum[i];
    for (int i = 0; i < 6; ++i) s.sum_sq[i] += child.sum_sq[i];
  }
  return sums;
}

void NdtGrid::generate(const std::vector<CellSums>& sums, const CellStatsSettings& settings) {
  gaussians_.reserve(sums.size());
  cell_of_gaussian_.reserve(sums.size());
  // C'⁻¹ with eigenvalues raised to λmax / ratio; no Gaussian for a cell with (almost) no spread: λmax
  // below `min_spread` (repeated points) or below (min_relative_spread · edge)² (a blob, not a surface
  // at this cell size).
  const double relative = settings.min_relative_spread * cell_edge_;
  const double least_spread = std::max(settings.min_spread, relative * relative);
  // The cells with enough points, a block at a time: their moments, then their information four cells
  // per vector (cells_information), then their Gaussians in the cells' order.
  constexpr std::size_t kBlock = 64;
  const CellSums* cells[kBlock];
  double means[kBlock][3], covariances[6 * kBlock], information[6 * kBlock];
  bool kept[kBlock];
  std::size_t filled = 0;
  const auto flush = [&] {
    ndt_detail::cells_information(covariances, filled, settings.max_eigen_ratio, least_spread, information,
                                  kept);
    for (std::size_t j = 0; j < filled; ++j) {
      if (!kept[j]) continue;
      CellGaussian g{};
      for (int i = 0; i < 3; ++i) g.mean[i] = static_cast<float>(means[j][i] + origin_(i));
      for (int e = 0; e < 6; ++e) g.inv_cov[e] = static_cast<float>(information[6 * j + e]);
      index_[static_cast<std::size_t>(cells[j]->cell)] = static_cast<std::int32_t>(gaussians_.size());
      modelled_points_ += static_cast<std::size_t>(cells[j]->count);
      gaussians_.push_back(g);
      cell_of_gaussian_.push_back(cells[j]->cell);
    }
    filled = 0;
  };
  for (const CellSums& s : sums) {
    index_[static_cast<std::size_t>(s.cell)] = -1;
    if (static_cast<std::size_t>(s.count) < settings.min_points) continue;
    cell_moments(s, means[filled], covariances + 6 * filled);
    cells[filled++] = &s;
    if (filled == kBlock) flush();
  }
  flush();
}

NdtGrid NdtGrid::build(const PointCloud& reference, const Eigen::Vector3d& origin, double cell_edge,
                       const Eigen::Vector3i& dims, const CellStatsSettings& settings,
                       std::size_t max_cells) {
  NdtGrid grid;
  if (grid.init(origin, cell_edge, dims, max_cells)) grid.generate(grid.split(reference), settings);
  return grid;
}

NdtGrid NdtGrid::build_over_bounds(const PointCloud& reference, double cell_edge,
                                   const CellStatsSettings& settings) {
  const Bounds b = reference.bounds();
  Eigen::Vector3i dims;
  for (int a = 0; a < 3; ++a)
    dims(a) = saturated_cell_count(std::ceil(static_cast<double>(b.extent()(a)) / cell_edge));
  if (!(cell_edge > 0.0) || !std::isfinite(cell_edge)) dims.setZero();
  return build(reference, b.min.cast<double>(), cell_edge, dims, settings);
}

Eigen::Matrix3d NdtGrid::covariance(int g) const {
  return information_of(gaussian(g)).inverse();
}

Eigen::Matrix3d NdtGrid::sqrt_information(int g) const {
  // C'⁻¹ = L Lᵀ: any square root serves the residual Lᵀe; the Cholesky factor gives a compact
  // upper-triangular Lᵀ.
  return Eigen::LLT<Eigen::Matrix3d>(information_of(gaussian(g))).matrixL().transpose();
}

Eigen::Vector3i NdtGrid::cell_coordinates(std::size_t cell) const {
  // init() caps a grid below 2³¹ cells: 32-bit divisions suffice (several times faster).
  const auto c = static_cast<std::uint32_t>(cell), nx = static_cast<std::uint32_t>(dims_.x()),
             ny = static_cast<std::uint32_t>(dims_.y());
  return {static_cast<int>(c % nx), static_cast<int>((c / nx) % ny), static_cast<int>(c / (nx * ny))};
}

Eigen::Vector3i NdtGrid::cell_of(int g) const {
  return cell_coordinates(static_cast<std::size_t>(cell_of_gaussian_[static_cast<std::size_t>(g)]));
}

LayerGeometry layer_geometry(const Bounds& bounds, int q, int layer) {
  LayerGeometry geometry;
  const Eigen::Vector3d extent = bounds.extent().cast<double>();
  const double largest = extent.maxCoeff();
  if (!(largest > 0.0) || !std::isfinite(largest) || q < 1 || layer < 0) return geometry;
  double volume = 1.0;
  int used_axes = 0;
  for (int a = 0; a < 3; ++a) {
    if (extent(a) > 1e-6 * largest) {
      volume *= extent(a);
      ++used_axes;
    }
  }
  const double cells = std::pow(static_cast<double>(q), layer);
  geometry.cell_edge = std::pow(volume / cells, 1.0 / used_axes);  // k = (V / qⁱ)^(1/3)
  for (int a = 0; a < 3; ++a)
    geometry.dims(a) = saturated_cell_count(std::ceil(extent(a) / geometry.cell_edge - 1e-9));
  return geometry;
}

bool LayerPyramidSettings::valid(std::string* why) const {
  const char* problem = nullptr;
  if (division < 2)
    problem = "division (q) must be at least 2";
  else if (layers < 1 || layers > 8)
    problem = "layers (n) must lie in [1, 8]";
  else if (!(bounds_quantile >= 0.0 && bounds_quantile < 0.25))
    problem = "bounds_quantile must lie in [0, 0.25)";
  if (problem && why) *why = problem;
  if (problem) return false;
  return cells.valid(why);
}

namespace {

/// True when every layer's cells split exactly into 2 × 2 × 2 of the next one: q = 8 over a volume
/// (the edge halves from layer to layer) and room in each layer for the parents of the next.
bool layers_nest(const std::vector<LayerGeometry>& g, int q) {
  if (q != 8) return false;
  for (std::size_t i = 0; i + 1 < g.size(); ++i) {
    if (!(g[i + 1].cell_edge > 0.0) ||
        std::abs(g[i].cell_edge - 2.0 * g[i + 1].cell_edge) > 1e-9 * g[i].cell_edge)
      return false;
    if (((g[i + 1].dims.array() + 1) / 2 > g[i].dims.array()).any()) return false;
  }
  return true;
}

constexpr std::size_t kMaxCells = std::size_t{1} << 27;  // NdtGrid::build's default

}  // namespace

Termination empty_model_reason(std::size_t reference_points, const NdtGrid& grid) {
  if (reference_points == 0) return Termination::kEmptyInput;
  return grid.too_large() ? Termination::kGridTooLarge : Termination::kNoGaussians;
}

std::vector<NdtGrid> build_layer_pyramid(const PointCloud& reference, const LayerPyramidSettings& settings) {
  return build_layer_pyramid(reference, settings, robust_bounds(reference, settings.bounds_quantile));
}

namespace {

std::vector<LayerGeometry> pyramid_geometry(const Bounds& bounds, const LayerPyramidSettings& settings) {
  std::vector<LayerGeometry> g;
  for (int i = 1; i <= settings.layers; ++i) g.push_back(layer_geometry(bounds, settings.division, i));
  return g;
}

}  // namespace

bool pyramid_nests(const Bounds& box, const LayerPyramidSettings& settings) {
  return settings.layers >= 1 && layers_nest(pyramid_geometry(box, settings), settings.division);
}

std::vector<NdtGrid> build_layer_pyramid(const PointCloud& reference, const LayerPyramidSettings& settings,
                                         const Bounds& bounds, NdtGrid* finer,
                                         const CellStatsSettings* finer_cells) {
  const Eigen::Vector3d origin = bounds.min.cast<double>();
  const auto n = static_cast<std::size_t>(std::max(settings.layers, 0));
  const std::vector<LayerGeometry> g = pyramid_geometry(bounds, settings);
  std::vector<NdtGrid> layers(n);
  if (finer) *finer = NdtGrid();
  // Nested layers: one pass over the points for the finest grid (layer n, or layer n + 1 when the
  // caller wants it too), each coarser layer from its children's sums, with edge 2^(n−i) times
  // layer n's (the geometry's edge up to rounding) so that a point's cell there is exactly the
  // parent of its finest cell.
  if (n >= 1 && (n > 1 || finer) && layers_nest(g, settings.division) &&
      layers[n - 1].init(origin, g[n - 1].cell_edge, g[n - 1].dims, kMaxCells)) {
    std::vector<CellSums> sums;
    if (finer && finer->init(origin, 0.5 * g[n - 1].cell_edge, 2 * g[n - 1].dims, kMaxCells)) {
      const std::vector<CellSums> children = finer->split(reference);
      sums = layers[n - 1].merge_children(children);
      finer->generate(children, finer_cells ? *finer_cells : settings.cells);
    } else {
      if (finer) *finer = NdtGrid();  // too many cells for layer n + 1: the caller builds its own
      sums = layers[n - 1].split(reference);
    }
    double edge = g[n - 1].cell_edge;
    for (std::size_t i = n - 1; i-- > 0;) {
      edge *= 2.0;
      layers[i].init(origin, edge, g[i].dims, kMaxCells);  // fewer cells than layer n
      std::vector<CellSums> parents = layers[i].merge_children(sums);
      layers[i + 1].generate(sums, settings.cells);
      sums = std::move(parents);
    }
    layers[0].generate(sums, settings.cells);
    return layers;
  }
  for (std::size_t i = 0; i < n; ++i)
    layers[i] = NdtGrid::build(reference, origin, g[i].cell_edge, g[i].dims, settings.cells);
  return layers;
}

}  // namespace sextant
