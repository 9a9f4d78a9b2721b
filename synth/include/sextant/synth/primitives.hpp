#pragma once
// Ray-castable primitives of the synthetic world: planar polygons (façades, roofs, walls),
// oriented boxes (cars, balconies, kerbs), vertical cylinders (poles, trunks), axis-aligned
// ellipsoids (foliage) and triangles (the ground mesh). Each intersect() returns the distance
// along the ray to the first hit in [0, max_range], or nothing. Directions are unit length.
#include <cmath>
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace sextant::synth {

struct Ray {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  ///< unit length
};

/// Entry and exit distance of a ray through a closed volume.
struct Span {
  double entry = 0.0;
  double exit = 0.0;
};

/// An axis-aligned box [min, max].
struct Box {
  Eigen::Vector3d min = Eigen::Vector3d::Zero(), max = Eigen::Vector3d::Zero();
  /// Distance along the ray to the first hit in [0, max_range], if any (slab method).
  std::optional<double> intersect(const Ray& ray, double max_range) const;
  std::optional<Span> span(const Ray& ray, double max_range) const;
  bool contains(const Eigen::Vector3d& p, double tolerance = 0.0) const;
};

/// A box of half extents `half` centred at `center`, rotated by `yaw` about the vertical axis.
class OrientedBox {
 public:
  OrientedBox() = default;
  OrientedBox(const Eigen::Vector3d& center, const Eigen::Vector3d& half, double yaw)
      : center_(center), half_(half), yaw_(yaw), cos_yaw_(std::cos(yaw)), sin_yaw_(std::sin(yaw)) {}

  const Eigen::Vector3d& center() const { return center_; }
  const Eigen::Vector3d& half() const { return half_; }  ///< half extents [m]
  double yaw() const { return yaw_; }                    ///< [rad]

  std::optional<double> intersect(const Ray& ray, double max_range) const;
  /// Distance of p from the box surface (0 on the surface, positive outside or inside).
  double surface_distance(const Eigen::Vector3d& p) const;
  /// Point in box coordinates.
  Eigen::Vector3d to_local(const Eigen::Vector3d& p) const;

 private:
  Eigen::Vector3d center_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d half_ = Eigen::Vector3d::Constant(0.5);
  double yaw_ = 0.0;
  double cos_yaw_ = 1.0, sin_yaw_ = 0.0;  // of yaw_, for every ray a cast tests against the box
};

/// A planar simple polygon (not necessarily convex), two-sided.
class Polygon {
 public:
  Polygon() = default;
  /// `vertices` must be planar (within 1e-6 m) and in order; the normal follows the right-hand
  /// rule of the vertex order.
  explicit Polygon(std::vector<Eigen::Vector3d> vertices);

  std::optional<double> intersect(const Ray& ray, double max_range) const;
  /// Whether p lies on the polygon within `tolerance` [m] of its plane.
  bool contains(const Eigen::Vector3d& p, double tolerance) const;
  /// Euclidean distance from p to the closed polygon [m].
  double distance(const Eigen::Vector3d& p) const;

  const std::vector<Eigen::Vector3d>& vertices() const { return vertices_; }
  const Eigen::Vector3d& normal() const { return normal_; }
  /// Plane n·x = d.
  double d() const { return d_; }
  double area() const { return area_; }

 private:
  bool inside_2d(const Eigen::Vector3d& p) const;

  std::vector<Eigen::Vector3d> vertices_;
  std::vector<Eigen::Vector2d> local_;  ///< vertices in the plane basis (u, v)
  Eigen::Vector3d normal_ = Eigen::Vector3d::UnitZ(), u_ = Eigen::Vector3d::UnitX(),
                  v_ = Eigen::Vector3d::UnitY();
  double d_ = 0.0;
  double area_ = 0.0;
};

/// A vertical cylinder with closed caps.
struct Cylinder {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  ///< axis position (x, y) [m]
  double radius = 0.1;                               ///< [m]
  double z_min = 0.0, z_max = 1.0;                   ///< [m]

  std::optional<double> intersect(const Ray& ray, double max_range) const;
  double surface_distance(const Eigen::Vector3d& p) const;
};

/// An ellipsoid with axis-aligned radii.
struct Ellipsoid {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d radii = Eigen::Vector3d::Ones();  ///< [m]

  std::optional<Span> span(const Ray& ray, double max_range) const;
  /// Value of |(p − c)/r|: 1 on the surface, < 1 inside.
  double normalized_radius(const Eigen::Vector3d& p) const;
};

/// A triangle (ground mesh), two-sided, Möller–Trumbore intersection.
struct Triangle {
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::UnitX(), c = Eigen::Vector3d::UnitY();

  std::optional<double> intersect(const Ray& ray, double max_range) const;
  double distance(const Eigen::Vector3d& p) const;  ///< Euclidean distance to the closed triangle [m]
};

}  // namespace sextant::synth
