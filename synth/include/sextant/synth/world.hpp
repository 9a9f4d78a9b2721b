#pragma once
// The synthetic world: ray-castable primitives in a uniform 2D grid, the ground mesh, and the
// true planar landmarks (façades, roofs, free-standing walls).
#include <array>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Core>

#include "sextant/synth/primitives.hpp"

namespace sextant::synth {

enum class ObjectKind : std::uint8_t {
  kGround,
  kKerb,
  kFacade,
  kRoof,
  kWall,
  kBalcony,
  kCar,
  kPole,
  kTrunk,
  kFoliage
};

/// "ground", "facade", ... (used in landmarks.txt and the preview).
const char* kind_name(ObjectKind kind);

using Shape = std::variant<Polygon, OrientedBox, Cylinder, Ellipsoid, Triangle>;

struct Primitive {
  Shape shape;
  ObjectKind kind = ObjectKind::kGround;
  int landmark = -1;  ///< index into World::landmarks, or −1 when not a planar landmark
};

/// A true planar patch: n·x = d (n unit, pointing out of the building), bounded by `polygon`.
struct Landmark {
  int id = 0;
  ObjectKind kind = ObjectKind::kFacade;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();
  double d = 0.0;
  std::vector<Eigen::Vector3d> polygon;  ///< world frame [m]
  double area = 0.0;                     ///< [m²]
};

/// A rectangular ground plan of the world, for the preview.
struct Footprint {
  std::vector<Eigen::Vector2d> outline;
  ObjectKind kind = ObjectKind::kFacade;
};

struct RayHit {
  double range = 0.0;  ///< distance to the surface (before noise) [m]
  int primitive = -1;  ///< index into World::primitives
  int landmark = -1;
};

/// Uniform 2D grid (x, y) over the world bounds; each cell lists the primitives whose xy
/// bounding box overlaps it (compressed rows), each with its vertical extent, so that a ray can
/// pass over (or under) a primitive without testing it.
class PrimitiveGrid {
 public:
  PrimitiveGrid() = default;
  PrimitiveGrid(const std::vector<Primitive>& primitives, Eigen::Vector2d min, Eigen::Vector2d max,
                double cell);

  Eigen::Vector2d min() const { return min_; }
  double cell() const { return cell_; }
  int nx() const { return nx_; }
  int ny() const { return ny_; }
  /// Primitive indices of cell (ix, iy): [begin, end) into indices().
  std::pair<const std::uint32_t*, const std::uint32_t*> cell_items(int ix, int iy) const;
  /// Vertical extent (z_min, z_max) of each entry of cell_items, in the same order.
  const std::array<float, 2>* cell_item_heights(int ix, int iy) const;
  /// Vertical extent of all of cell (ix, iy)'s items together (empty: z_min > z_max), so that a
  /// ray passing over or under all of them skips the cell.
  const std::array<float, 2>& cell_heights(int ix, int iy) const {
    return cell_heights_[static_cast<std::size_t>(iy) * nx_ + ix];
  }

 private:
  Eigen::Vector2d min_ = Eigen::Vector2d::Zero();
  double cell_ = 1.0;
  int nx_ = 0, ny_ = 0;
  std::vector<std::uint32_t> offsets_;
  std::vector<std::uint32_t> items_;
  std::vector<std::array<float, 2>> item_heights_;
  std::vector<std::array<float, 2>> cell_heights_;
};

class World {
 public:
  std::vector<Primitive> primitives;
  std::vector<Landmark> landmarks;
  std::vector<Footprint> footprints;  ///< buildings, walls, cars (preview)
  Eigen::Vector2d min = Eigen::Vector2d::Zero(), max = Eigen::Vector2d::Zero();  ///< xy bounds [m]

  double foliage_porosity = 0.0;     ///< see WorldSettings
  double foliage_penetration = 0.0;  ///< [m]

  /// Ground mesh heights on a regular lattice (row-major, x fastest).
  double ground_cell = 4.0;
  int ground_nx = 0, ground_ny = 0;
  std::vector<double> ground_heights;

  /// Builds the acceleration grid; call after the primitives are final.
  void build_grid(double cell);
  /// Height of the ground mesh at (x, y) (clamped to the mesh) [m].
  double ground_height(double x, double y) const;

  /// First surface hit by the ray within max_range. `ray_key` seeds the per-ray decisions for
  /// porous foliage (pass through or not, penetration depth), so the result is a pure
  /// function of the ray and the key.
  std::optional<RayHit> cast(const Ray& ray, double max_range, std::uint64_t ray_key) const;

  /// Distance from p to primitive i's surface (for foliage: 0 inside the volume) [m].
  double distance_to(int primitive, const Eigen::Vector3d& p) const;

 private:
  PrimitiveGrid grid_;
};

/// xy bounding box of a primitive, as (min, max).
std::pair<Eigen::Vector2d, Eigen::Vector2d> xy_bounds(const Shape& shape);
/// Vertical extent of a primitive, as (z_min, z_max).
std::pair<double, double> z_bounds(const Shape& shape);

}  // namespace sextant::synth
