#include "sextant/synth/world.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

namespace sextant::synth {
namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

double unit_from_bits(std::uint64_t bits) {
  return static_cast<double>(bits >> 11) * 0x1.0p-53;
}

struct XyBounds {
  std::pair<Eigen::Vector2d, Eigen::Vector2d> operator()(const Polygon& p) const {
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const auto& v : p.vertices()) {
      lo = lo.cwiseMin(v.head<2>());
      hi = hi.cwiseMax(v.head<2>());
    }
    return {lo, hi};
  }
  std::pair<Eigen::Vector2d, Eigen::Vector2d> operator()(const OrientedBox& b) const {
    const double c = std::abs(std::cos(b.yaw())), s = std::abs(std::sin(b.yaw()));
    const Eigen::Vector2d r(c * b.half().x() + s * b.half().y(), s * b.half().x() + c * b.half().y());
    return {b.center().head<2>() - r, b.center().head<2>() + r};
  }
  std::pair<Eigen::Vector2d, Eigen::Vector2d> operator()(const Cylinder& c) const {
    return {c.center.array() - c.radius, c.center.array() + c.radius};
  }
  std::pair<Eigen::Vector2d, Eigen::Vector2d> operator()(const Ellipsoid& e) const {
    return {e.center.head<2>() - e.radii.head<2>(), e.center.head<2>() + e.radii.head<2>()};
  }
  std::pair<Eigen::Vector2d, Eigen::Vector2d> operator()(const Triangle& t) const {
    return {t.a.head<2>().cwiseMin(t.b.head<2>()).cwiseMin(t.c.head<2>()),
            t.a.head<2>().cwiseMax(t.b.head<2>()).cwiseMax(t.c.head<2>())};
  }
};

struct ZBounds {
  std::pair<double, double> operator()(const Polygon& p) const {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& v : p.vertices()) {
      lo = std::min(lo, v.z());
      hi = std::max(hi, v.z());
    }
    return {lo, hi};
  }
  std::pair<double, double> operator()(const OrientedBox& b) const {
    return {b.center().z() - b.half().z(), b.center().z() + b.half().z()};
  }
  std::pair<double, double> operator()(const Cylinder& c) const { return {c.z_min, c.z_max}; }
  std::pair<double, double> operator()(const Ellipsoid& e) const {
    return {e.center.z() - e.radii.z(), e.center.z() + e.radii.z()};
  }
  std::pair<double, double> operator()(const Triangle& t) const {
    return {std::min({t.a.z(), t.b.z(), t.c.z()}), std::max({t.a.z(), t.b.z(), t.c.z()})};
  }
};

// A primitive's heights are kept as floats beside its index; this margin [m] covers their rounding.
constexpr double kHeightMargin = 1e-3;

}  // namespace

const char* kind_name(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::kGround: return "ground";
    case ObjectKind::kKerb: return "kerb";
    case ObjectKind::kFacade: return "facade";
    case ObjectKind::kRoof: return "roof";
    case ObjectKind::kWall: return "wall";
    case ObjectKind::kBalcony: return "balcony";
    case ObjectKind::kCar: return "car";
    case ObjectKind::kPole: return "pole";
    case ObjectKind::kTrunk: return "trunk";
    case ObjectKind::kFoliage: return "foliage";
  }
  return "unknown";
}

std::pair<Eigen::Vector2d, Eigen::Vector2d> xy_bounds(const Shape& shape) {
  return std::visit(XyBounds{}, shape);
}

std::pair<double, double> z_bounds(const Shape& shape) {
  return std::visit(ZBounds{}, shape);
}

PrimitiveGrid::PrimitiveGrid(const std::vector<Primitive>& primitives, Eigen::Vector2d min,
                             Eigen::Vector2d max, double cell)
    : min_(min), cell_(cell) {
  nx_ = std::max(1, static_cast<int>(std::ceil((max.x() - min.x()) / cell)));
  ny_ = std::max(1, static_cast<int>(std::ceil((max.y() - min.y()) / cell)));
  // A primitive is listed in the cells its xy box overlaps: [lo, hi] against each cell's [start,
  // start + cell). A box that ends exactly on a cell's start (the ground mesh's triangles, whose
  // spacing is the grid's) is not listed in that cell: a ray there can only meet it on the shared
  // border, where the cell before finds it at its exit.
  const auto first_cell = [](double lo, double origin, double edge, int n) {
    return std::clamp(static_cast<int>(std::floor((lo - origin) / edge)), 0, n - 1);
  };
  const auto last_cell = [&](double lo, double hi, double origin, double edge, int n) {
    const int last = std::clamp(static_cast<int>(std::ceil((hi - origin) / edge)) - 1, 0, n - 1);
    return std::max(first_cell(lo, origin, edge, n), last);
  };
  // Two passes: count, then fill (compressed rows).
  std::vector<std::uint32_t> counts(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  std::vector<std::array<int, 4>> ranges(primitives.size());
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    const auto [lo, hi] = xy_bounds(primitives[i].shape);
    ranges[i] = {first_cell(lo.x(), min_.x(), cell_, nx_), last_cell(lo.x(), hi.x(), min_.x(), cell_, nx_),
                 first_cell(lo.y(), min_.y(), cell_, ny_), last_cell(lo.y(), hi.y(), min_.y(), cell_, ny_)};
    for (int iy = ranges[i][2]; iy <= ranges[i][3]; ++iy)
      for (int ix = ranges[i][0]; ix <= ranges[i][1]; ++ix)
        ++counts[static_cast<std::size_t>(iy) * nx_ + ix + 1];
  }
  for (std::size_t c = 1; c < counts.size(); ++c) counts[c] += counts[c - 1];
  offsets_ = counts;
  items_.resize(counts.back());
  item_heights_.resize(counts.back());
  cell_heights_.assign(static_cast<std::size_t>(nx_) * ny_,
                       {std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()});
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    const auto [z_lo, z_hi] = z_bounds(primitives[i].shape);
    for (int iy = ranges[i][2]; iy <= ranges[i][3]; ++iy)
      for (int ix = ranges[i][0]; ix <= ranges[i][1]; ++ix) {
        const std::uint32_t slot = counts[static_cast<std::size_t>(iy) * nx_ + ix]++;
        items_[slot] = static_cast<std::uint32_t>(i);
        item_heights_[slot] = {static_cast<float>(z_lo), static_cast<float>(z_hi)};
        auto& cell = cell_heights_[static_cast<std::size_t>(iy) * nx_ + ix];
        cell = {std::min(cell[0], item_heights_[slot][0]), std::max(cell[1], item_heights_[slot][1])};
      }
  }
}

std::pair<const std::uint32_t*, const std::uint32_t*> PrimitiveGrid::cell_items(int ix, int iy) const {
  const std::size_t c = static_cast<std::size_t>(iy) * nx_ + ix;
  return {items_.data() + offsets_[c], items_.data() + offsets_[c + 1]};
}

const std::array<float, 2>* PrimitiveGrid::cell_item_heights(int ix, int iy) const {
  return item_heights_.data() + offsets_[static_cast<std::size_t>(iy) * nx_ + ix];
}

void World::build_grid(double cell) {
  grid_ = PrimitiveGrid(primitives, min, max, cell);
}

double World::ground_height(double x, double y) const {
  if (ground_nx < 2 || ground_ny < 2) return 0.0;
  const double gx = std::clamp((x - min.x()) / ground_cell, 0.0, ground_nx - 1.000001);
  const double gy = std::clamp((y - min.y()) / ground_cell, 0.0, ground_ny - 1.000001);
  const int ix = static_cast<int>(gx), iy = static_cast<int>(gy);
  const double fx = gx - ix, fy = gy - iy;
  const auto h = [&](int i, int j) { return ground_heights[static_cast<std::size_t>(j) * ground_nx + i]; };
  // The mesh splits each cell along the diagonal (0,0)–(1,1), as the world builder does.
  if (fx >= fy)
    return h(ix, iy) + fx * (h(ix + 1, iy) - h(ix, iy)) + fy * (h(ix + 1, iy + 1) - h(ix + 1, iy));
  return h(ix, iy) + fy * (h(ix, iy + 1) - h(ix, iy)) + fx * (h(ix + 1, iy + 1) - h(ix, iy + 1));
}

std::optional<RayHit> World::cast(const Ray& ray, double max_range, std::uint64_t ray_key) const {
  const double cell = grid_.cell();
  const Eigen::Vector2d o = (ray.origin.head<2>() - grid_.min()) / cell;  // in cell units
  int ix = static_cast<int>(std::floor(o.x())), iy = static_cast<int>(std::floor(o.y()));
  if (ix < 0 || iy < 0 || ix >= grid_.nx() || iy >= grid_.ny()) return std::nullopt;

  // Amanatides–Woo traversal; t is the distance along the 3D ray.
  const double dx = ray.direction.x(), dy = ray.direction.y();
  const double inf = std::numeric_limits<double>::infinity();
  const int step_x = dx > 0 ? 1 : -1, step_y = dy > 0 ? 1 : -1;
  const double t_delta_x = dx != 0.0 ? cell / std::abs(dx) : inf;
  const double t_delta_y = dy != 0.0 ? cell / std::abs(dy) : inf;
  double t_max_x = dx != 0.0 ? ((dx > 0 ? ix + 1 - o.x() : o.x() - ix) * cell) / std::abs(dx) : inf;
  double t_max_y = dy != 0.0 ? ((dy > 0 ? iy + 1 - o.y() : o.y() - iy) * cell) / std::abs(dy) : inf;

  RayHit best;
  best.range = inf;
  double t_enter = 0.0;  // where the ray enters the current cell
  while (true) {
    auto [begin, end] = grid_.cell_items(ix, iy);
    const std::array<float, 2>* heights = grid_.cell_item_heights(ix, iy);
    // A hit on a primitive of this cell that lies in another cell is found there (the primitive is
    // listed in every cell its xy box touches), so only heights the ray has inside this cell can
    // be hit here. The border cells also hold what lies beyond the grid: no limit there.
    const bool border = ix == 0 || iy == 0 || ix == grid_.nx() - 1 || iy == grid_.ny() - 1;
    const double t_leave = border ? inf : std::min(t_max_x, t_max_y);
    const double t_last = std::min({t_leave, max_range, best.range});
    const double z_enter = ray.origin.z() + t_enter * ray.direction.z();
    const double z_last = std::isfinite(t_last)     ? ray.origin.z() + t_last * ray.direction.z()
                          : ray.direction.z() > 0.0 ? inf
                          : ray.direction.z() < 0.0 ? -inf
                                                    : z_enter;
    const double z_low = std::min(z_enter, z_last) - kHeightMargin;
    const double z_high = std::max(z_enter, z_last) + kHeightMargin;
    const std::array<float, 2>& all = grid_.cell_heights(ix, iy);
    if (all[1] < z_low || all[0] > z_high) end = begin;  // passes over or under everything here
    for (const std::uint32_t* it = begin; it != end; ++it, ++heights) {
      if ((*heights)[1] < z_low || (*heights)[0] > z_high) continue;  // passes over or under it
      const Primitive& prim = primitives[*it];
      std::optional<double> t;
      if (const auto* e = std::get_if<Ellipsoid>(&prim.shape)) {
        const auto span = e->span(ray, std::min(max_range, best.range));
        if (!span) continue;
        const std::uint64_t h = splitmix64(ray_key ^ splitmix64(*it));
        if (unit_from_bits(h) < foliage_porosity) continue;  // passes through the gaps
        const double depth =
            unit_from_bits(splitmix64(h)) * std::min(foliage_penetration, span->exit - span->entry);
        t = span->entry + depth;
      } else {
        t = std::visit(
            [&](const auto& s) -> std::optional<double> {
              if constexpr (std::is_same_v<std::decay_t<decltype(s)>, Ellipsoid>) {
                return std::nullopt;
              } else {
                return s.intersect(ray, std::min(max_range, best.range));
              }
            },
            prim.shape);
      }
      if (t && *t < best.range) {
        best.range = *t;
        best.primitive = static_cast<int>(*it);
        best.landmark = prim.landmark;
      }
    }
    const double t_exit = std::min(t_max_x, t_max_y);
    if (best.range <= t_exit || t_exit > max_range) break;
    t_enter = t_exit;
    if (t_max_x < t_max_y) {
      ix += step_x;
      t_max_x += t_delta_x;
    } else {
      iy += step_y;
      t_max_y += t_delta_y;
    }
    if (ix < 0 || iy < 0 || ix >= grid_.nx() || iy >= grid_.ny()) break;
  }
  if (best.primitive < 0 || best.range > max_range) return std::nullopt;
  return best;
}

double World::distance_to(int primitive, const Eigen::Vector3d& p) const {
  const Primitive& prim = primitives.at(static_cast<std::size_t>(primitive));
  struct Distance {
    const Eigen::Vector3d& p;
    double operator()(const Polygon& s) const { return s.distance(p); }
    double operator()(const OrientedBox& s) const { return s.surface_distance(p); }
    double operator()(const Cylinder& s) const { return s.surface_distance(p); }
    double operator()(const Ellipsoid& s) const {
      // Foliage returns come from inside the volume: 0 inside, else the radial excess.
      const double r = s.normalized_radius(p);
      return r <= 1.0 ? 0.0 : (r - 1.0) * s.radii.minCoeff();
    }
    double operator()(const Triangle& s) const { return s.distance(p); }
  };
  return std::visit(Distance{p}, prim.shape);
}

}  // namespace sextant::synth
