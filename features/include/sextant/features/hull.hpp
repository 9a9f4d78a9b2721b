#pragma once
// Projection of plane inliers to their principal plane, 2D convex hull (Andrew's monotone
// chain), minimum-area bounding rectangle, and back-projection to 3D (§3.3.1.2, eqs. (3.26)–(3.32)).
#include <vector>

#include <Eigen/Core>

namespace sextant {

/// Convex hull, counter-clockwise, no repeated or collinear vertices. Fewer than 3 distinct
/// points give the distinct points (a degenerate hull of area 0).
std::vector<Eigen::Vector2d> convex_hull_2d(std::vector<Eigen::Vector2d> points);

/// Shoelace area of a simple polygon (positive for counter-clockwise) [m²].
double polygon_area(const std::vector<Eigen::Vector2d>& polygon);

struct Rectangle2d {
  std::vector<Eigen::Vector2d> corners;  ///< 4 corners counter-clockwise (empty for an empty hull)
  double area = 0.0;                     ///< [m²]
};

/// Minimum-area enclosing rectangle of a convex polygon: one side lies on a hull edge
/// (Freeman & Shapira), so every edge direction is tried.
Rectangle2d min_area_rectangle(const std::vector<Eigen::Vector2d>& hull);

/// A 2D frame in a plane: p3 = origin + axes·p2; p2 = axesᵀ(p3 − origin), eqs. (3.30)–(3.32).
struct PlaneFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 3, 2> axes = Eigen::Matrix<double, 3, 2>::Identity();  ///< R' = [v1 v2]

  Eigen::Vector2d project(const Eigen::Vector3d& p) const { return axes.transpose() * (p - origin); }
  Eigen::Vector3d lift(const Eigen::Vector2d& q) const { return origin + axes * q; }
};

/// Frame spanned by the major principal axis and n × v1, a right-handed (v1, v2, n) basis. The
/// origin is the centroid rather than the first point Γ_0 of eq. (3.26), so the lifted hull lies
/// on the fitted plane.
PlaneFrame principal_frame(const Eigen::Vector3d& centroid, const Eigen::Vector3d& normal,
                           const Eigen::Vector3d& major_axis);

struct PlaneOutline {
  std::vector<Eigen::Vector3d> hull;       ///< Δ_XYZ, eq. (3.32)
  std::vector<Eigen::Vector3d> rectangle;  ///< min-area bounding rectangle in 3D (4 corners)
  double area = 0.0;                       ///< hull area [m²]
};

/// Projects the points into `frame` (eq. (3.31)), computes hull and rectangle, lifts them back.
PlaneOutline compute_outline(const std::vector<Eigen::Vector3d>& points, const PlaneFrame& frame);

}  // namespace sextant
