#include "sextant/features/hull.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace sextant {

namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

bool lexicographic_less(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

}  // namespace

// Andrew's monotone chain: sort by x then y, build the lower and upper chains.
std::vector<Eigen::Vector2d> convex_hull_2d(std::vector<Eigen::Vector2d> points) {
  points.erase(
      std::remove_if(points.begin(), points.end(), [](const Eigen::Vector2d& p) { return !p.allFinite(); }),
      points.end());
  std::sort(points.begin(), points.end(), lexicographic_less);
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (const auto& p : points) {  // lower chain
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
    hull[k++] = p;
  }
  const std::size_t lower = k + 1;
  for (std::size_t i = points.size() - 1; i-- > 0;) {  // upper chain
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // the last point repeats the first
  return hull;
}

double polygon_area(const std::vector<Eigen::Vector2d>& polygon) {
  if (polygon.size() < 3) return 0.0;
  double twice = 0.0;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    twice += polygon[j].x() * polygon[i].y() - polygon[i].x() * polygon[j].y();
  }
  return 0.5 * twice;
}

Rectangle2d min_area_rectangle(const std::vector<Eigen::Vector2d>& hull) {
  Rectangle2d best;
  if (hull.empty()) return best;
  if (hull.size() == 1) {
    best.corners.assign(4, hull.front());
    return best;
  }
  best.area = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d edge = hull[(i + 1) % hull.size()] - hull[i];
    const double length = edge.norm();
    if (!(length > 0.0)) continue;
    const Eigen::Vector2d u = edge / length, v(-u.y(), u.x());
    double umin = std::numeric_limits<double>::infinity(), umax = -umin, vmin = umin, vmax = -umin;
    for (const auto& p : hull) {
      const double a = u.dot(p), b = v.dot(p);
      umin = std::min(umin, a), umax = std::max(umax, a);
      vmin = std::min(vmin, b), vmax = std::max(vmax, b);
    }
    const double area = (umax - umin) * (vmax - vmin);
    if (area < best.area) {
      best.area = area;
      best.corners = {umin * u + vmin * v, umax * u + vmin * v, umax * u + vmax * v, umin * u + vmax * v};
    }
  }
  return best;
}

PlaneFrame principal_frame(const Eigen::Vector3d& centroid, const Eigen::Vector3d& normal,
                           const Eigen::Vector3d& major_axis) {
  PlaneFrame frame;
  frame.origin = centroid;
  Eigen::Vector3d v1 = major_axis - normal * normal.dot(major_axis);
  if (!(v1.norm() > 1e-9)) v1 = normal.unitOrthogonal();
  v1.normalize();
  frame.axes.col(0) = v1;                // eq. (3.30): R = [v1 v2]
  frame.axes.col(1) = normal.cross(v1);  // right-handed (v1, v2, n)
  return frame;
}

PlaneOutline compute_outline(const std::vector<Eigen::Vector3d>& points, const PlaneFrame& frame) {
  PlaneOutline out;
  std::vector<Eigen::Vector2d> projected;  // eq. (3.31): Δ_XY = R B
  projected.reserve(points.size());
  for (const auto& p : points) projected.push_back(frame.project(p));
  const std::vector<Eigen::Vector2d> hull = convex_hull_2d(std::move(projected));
  out.area = std::abs(polygon_area(hull));
  for (const auto& q : hull) out.hull.push_back(frame.lift(q));  // eq. (3.32)
  for (const auto& q : min_area_rectangle(hull).corners) out.rectangle.push_back(frame.lift(q));
  return out;
}

}  // namespace sextant
