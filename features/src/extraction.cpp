#include "sextant/features/extraction.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>

#include <Eigen/Eigenvalues>

#include "sextant/core/units.hpp"

namespace sextant {

namespace {

using Clock = std::chrono::steady_clock;

// Packs integer cell coordinates (21 bits each, offset to non-negative) into one key.
std::uint64_t cell_key(const Eigen::Vector3f& p, const Eigen::Vector3d& origin, double inv_cell) {
  constexpr std::int64_t kHalf = std::int64_t{1} << 20;
  std::uint64_t key = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double c = std::floor((static_cast<double>(p[axis]) - origin[axis]) * inv_cell);
    const std::int64_t clamped = static_cast<std::int64_t>(std::clamp(c, -double(kHalf), double(kHalf - 1)));
    key = (key << 21) | static_cast<std::uint64_t>(clamped + kHalf);
  }
  return key;
}

std::size_t count_distinct(PointsView points, const std::vector<std::size_t>& indices) {
  std::vector<std::array<float, 3>> copy;
  copy.reserve(indices.size());
  for (std::size_t i : indices) copy.push_back({points[i].x(), points[i].y(), points[i].z()});
  std::sort(copy.begin(), copy.end());
  return static_cast<std::size_t>(std::unique(copy.begin(), copy.end()) - copy.begin());
}

struct Hypothesis {
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();
  float d = 0.0f;
  std::size_t inliers = 0;
};

std::size_t count_inliers(PointsView points, const std::vector<std::size_t>& indices,
                          const Eigen::Vector3f& n, float d, float threshold) {
  std::size_t count = 0;
  for (std::size_t i : indices) count += std::abs(n.dot(points[i]) - d) <= threshold ? 1 : 0;
  return count;
}

std::vector<std::size_t> collect_inliers(PointsView points, const std::vector<std::size_t>& indices,
                                         const Plane& plane, double threshold) {
  std::vector<std::size_t> out;
  for (std::size_t i : indices) {
    if (std::abs(plane.signed_distance(points[i].cast<double>())) <= threshold) out.push_back(i);
  }
  return out;
}

// RANSAC [16]: planes through three random distinct points; the hypothesis with most inliers.
// The number of hypotheses adapts to the best inlier share w: N = log(1 − p) / log(1 − w³).
Hypothesis ransac_plane(PointsView points, const std::vector<std::size_t>& indices,
                        const PlaneExtractionSettings& s, Rng& rng) {
  Hypothesis best;
  const std::size_t n = indices.size();
  const float threshold = static_cast<float>(s.distance_threshold);
  double needed = s.ransac_iterations;
  for (int iteration = 0; iteration < s.ransac_iterations && iteration < needed; ++iteration) {
    const std::size_t i0 = rng.index(n), i1 = rng.index(n), i2 = rng.index(n);
    if (i0 == i1 || i0 == i2 || i1 == i2) continue;
    const Eigen::Vector3f& a = points[indices[i0]];
    const Eigen::Vector3f u = points[indices[i1]] - a, v = points[indices[i2]] - a;
    const Eigen::Vector3f normal = u.cross(v);
    const float norm = normal.norm();
    if (!(norm > 1e-6f * u.norm() * v.norm())) continue;  // (nearly) collinear sample
    Hypothesis h;
    h.normal = normal / norm;
    h.d = h.normal.dot(a);
    h.inliers = count_inliers(points, indices, h.normal, h.d, threshold);
    if (h.inliers <= best.inliers) continue;
    best = h;
    const double w = static_cast<double>(best.inliers) / static_cast<double>(n);
    const double miss = 1.0 - w * w * w;
    needed = miss <= 0.0 ? 0.0 : std::log(1.0 - s.ransac_confidence) / std::log(miss);
  }
  return best;
}

enum class CellVerdict { ok, too_few, duplicated, collinear };

CellVerdict classify_cell(PointsView points, const std::vector<std::size_t>& indices,
                          const PlaneExtractionSettings& s) {
  if (indices.size() < s.min_inliers) return CellVerdict::too_few;
  if (count_distinct(points, indices) < s.min_inliers) return CellVerdict::duplicated;
  const PlaneFit fit = fit_plane_pca(compute_moments(points, indices));
  // All points on a line (within the inlier band): any plane through it would be arbitrary.
  if (!fit.ok || std::sqrt(std::max(0.0, fit.eigenvalues(1))) <= s.distance_threshold)
    return CellVerdict::collinear;
  return CellVerdict::ok;
}

void extract_in_cell(PointsView points, std::vector<std::size_t> remaining, const PlaneExtractionSettings& s,
                     PlaneRefit refit, Rng& rng, PlaneExtraction* out) {
  switch (classify_cell(points, remaining, s)) {
    case CellVerdict::too_few: ++out->stats.cells_too_few_points; return;
    case CellVerdict::duplicated: ++out->stats.cells_duplicated_points; return;
    case CellVerdict::collinear: ++out->stats.cells_collinear; return;
    case CellVerdict::ok: break;
  }
  int found = 0;
  for (; found < s.max_planes_per_cell && remaining.size() >= s.min_inliers; ++found) {
    const Hypothesis h = ransac_plane(points, remaining, s, rng);
    const double needed = std::max(static_cast<double>(s.min_inliers), s.min_inlier_ratio * remaining.size());
    if (static_cast<double>(h.inliers) < needed) break;
    Plane plane;
    plane.normal = h.normal.cast<double>();
    plane.d = h.d;
    // Refit on the inliers (eqs. (3.22)–(3.25) or PCA), then once more on the refit's inliers.
    PlaneFit fit;
    std::vector<std::size_t> inliers = collect_inliers(points, remaining, plane, s.distance_threshold);
    for (int pass = 0; pass < (s.refit_inliers ? 2 : 0); ++pass) {
      fit = fit_plane(points, inliers, refit);
      if (!fit.ok) break;
      inliers = collect_inliers(points, remaining, fit.plane, s.distance_threshold);
    }
    if ((s.refit_inliers && !fit.ok) || static_cast<double>(inliers.size()) < needed) break;
    fit = fit_plane(points, inliers, refit);
    if (!fit.ok || std::sqrt(std::max(0.0, fit.eigenvalues(1))) <= s.distance_threshold) break;  // a line
    std::vector<std::size_t> rest;
    rest.reserve(remaining.size() - inliers.size());
    std::set_difference(remaining.begin(), remaining.end(), inliers.begin(), inliers.end(),
                        std::back_inserter(rest));
    out->cell_planes.push_back(make_landmark(points, std::move(inliers), fit, Eigen::Vector3d::Zero()));
    remaining = std::move(rest);
  }
  if (found == 0) ++out->stats.cells_without_plane;
}

struct CellSplit {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double edge = 1.0;
};

// The cells: cubes of cell_size at the origin, or layer split_layer of the cloud's own ML-NDT split
// (Table 3.2's Split(S, q, n); §3.2: edge k = (V / qⁱ)^(1/3) over the bounding box, axes of no extent
// left out of V as the pyramid does, ndt_grid.hpp layer_geometry).
CellSplit cell_split(PointsView points, const PlaneExtractionSettings& s) {
  CellSplit split;
  split.edge = s.cell_size;
  if (s.split_layer == 0) return split;
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d high = -low;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) continue;
    low = low.cwiseMin(points[i].cast<double>());
    high = high.cwiseMax(points[i].cast<double>());
  }
  if (!(high.x() >= low.x())) return split;  // no finite point: nothing to split
  const Eigen::Vector3d extent = high - low;
  const double largest = extent.maxCoeff();
  if (!(largest > 0.0)) return split;  // one point (repeated): any cell holds it
  double volume = 1.0;
  int axes = 0;
  for (int a = 0; a < 3; ++a) {
    if (extent(a) > 1e-6 * largest) {
      volume *= extent(a);
      ++axes;
    }
  }
  split.origin = low;
  split.edge = std::pow(volume / std::pow(static_cast<double>(s.split_division), s.split_layer), 1.0 / axes);
  return split;
}

void check(const PlaneExtractionSettings& settings) {
  std::string why;
  if (!settings.valid(&why)) throw std::invalid_argument("invalid plane extraction settings: " + why);
}

}  // namespace

bool PlaneExtractionSettings::valid(std::string* why) const {
  auto fail = [&](const std::string& text) {
    if (why) *why = text;
    return false;
  };
  PlaneRefit method;
  if (!(cell_size > 0.0 && cell_size <= kMaxSettingLength))
    return fail("cell_size must be positive and at most 1000 m");
  if (!(distance_threshold > 0.0 && distance_threshold <= cell_size))
    return fail("distance_threshold must be positive and at most cell_size");
  if (ransac_iterations < 1) return fail("ransac_iterations must be ≥ 1");
  if (!(ransac_confidence > 0.0 && ransac_confidence < 1.0))
    return fail("ransac_confidence must be in (0, 1)");
  if (min_inliers < 3) return fail("min_inliers must be ≥ 3");
  if (!(min_inlier_ratio >= 0.0 && min_inlier_ratio <= 1.0))
    return fail("min_inlier_ratio must be in [0, 1]");
  if (max_planes_per_cell < 1) return fail("max_planes_per_cell must be ≥ 1");
  if (!from_string(refit, &method)) return fail("refit must be 'pca' or 'svd'");
  if (split_layer < 0 || split_layer > 8) return fail("split_layer must be in [0, 8]");
  if (split_division < 2) return fail("split_division must be ≥ 2");
  if (!merge_thresholds.valid(why)) return false;
  if (!(horizontal_max_tilt_deg >= 0.0 && horizontal_max_tilt_deg <= 90.0))
    return fail("horizontal_max_tilt_deg must be in [0, 90]");
  if (!(min_landmark_area >= 0.0 && std::isfinite(min_landmark_area)))
    return fail("min_landmark_area must be ≥ 0");
  return true;
}

PlaneExtractionSettings thesis_feature_sampling() {
  PlaneExtractionSettings s;
  s.split_layer = 4;
  s.split_division = 8;
  s.max_planes_per_cell = 1;
  s.min_inliers = 11;  // "exceeds a threshold value (practically 10)"
  s.min_inlier_ratio = 0.0;
  s.refit_inliers = false;
  return s;
}

std::vector<std::size_t> PlaneExtraction::cell_inlier_indices() const {
  std::vector<std::size_t> out;
  for (const auto& plane : cell_planes) out.insert(out.end(), plane.inliers.begin(), plane.inliers.end());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

PlaneExtraction extract_cell_planes(const PointCloud& cloud, const PlaneExtractionSettings& settings,
                                    Rng& rng) {
  check(settings);
  const auto start = Clock::now();
  PlaneExtraction out;
  PlaneRefit refit = PlaneRefit::pca;
  from_string(settings.refit, &refit);
  const PointsView points = cloud.points();

  // Splitting: (cell key, point index) sorted by key, so each cell is a contiguous run.
  const CellSplit split = cell_split(points, settings);
  out.stats.cell_edge = split.edge;
  const double inv_cell = 1.0 / split.edge;
  std::vector<std::pair<std::uint64_t, std::size_t>> keyed;
  keyed.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) {
      ++out.stats.non_finite_points;
      continue;
    }
    keyed.emplace_back(cell_key(points[i], split.origin, inv_cell), i);
  }
  out.stats.points = keyed.size();
  std::sort(keyed.begin(), keyed.end());

  std::vector<std::size_t> cell;
  for (std::size_t begin = 0; begin < keyed.size();) {
    std::size_t end = begin;
    cell.clear();
    while (end < keyed.size() && keyed[end].first == keyed[begin].first) cell.push_back(keyed[end++].second);
    ++out.stats.cells;
    extract_in_cell(points, cell, settings, refit, rng, &out);
    begin = end;
  }
  out.stats.cell_planes = out.cell_planes.size();
  out.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return out;
}

PlaneExtraction extract_planes(const PointCloud& cloud, const PlaneExtractionSettings& settings, Rng& rng) {
  const auto start = Clock::now();
  PlaneExtraction out = extract_cell_planes(cloud, settings, rng);
  std::vector<PlaneLandmark> merged;
  if (settings.merge) {
    merged = merge_planes(out.cell_planes, settings.merge_thresholds).planes;
  } else {
    merged = out.cell_planes;
  }
  out.stats.merged_planes = merged.size();
  for (auto& plane : merged) {
    if (settings.remove_horizontal &&
        tilt_from_horizontal_deg(plane.plane) < settings.horizontal_max_tilt_deg) {
      ++out.stats.horizontal_removed;
    } else if (plane.area < settings.min_landmark_area ||
               plane.inlier_count < settings.min_landmark_inliers) {
      ++out.stats.too_small_removed;
    } else {
      std::sort(plane.inliers.begin(), plane.inliers.end());
      out.landmarks.push_back(std::move(plane));
    }
  }
  out.stats.landmarks = out.landmarks.size();
  out.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return out;
}

}  // namespace sextant
