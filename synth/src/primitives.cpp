#include "sextant/synth/primitives.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace sextant::synth {
namespace {

constexpr double kParallel = 1e-12;

Eigen::Vector3d rotate_z(const Eigen::Vector3d& p, double c, double s) {
  return {c * p.x() - s * p.y(), s * p.x() + c * p.y(), p.z()};
}

/// Smallest root in [0, max_range] of a·t² + b·t + c = 0, both roots in `roots`.
bool solve_quadratic(double a, double b, double c, double* t0, double* t1) {
  if (std::abs(a) < kParallel) return false;
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return false;
  const double root = std::sqrt(disc);
  // Numerically stable form.
  const double q = -0.5 * (b + (b < 0.0 ? -root : root));
  double r0 = q / a;
  double r1 = q != 0.0 ? c / q : r0;
  if (r0 > r1) std::swap(r0, r1);
  *t0 = r0;
  *t1 = r1;
  return true;
}

}  // namespace

std::optional<Span> Box::span(const Ray& ray, double max_range) const {
  double t_near = 0.0, t_far = max_range;
  for (int axis = 0; axis < 3; ++axis) {
    const double dir = ray.direction[axis];
    if (std::abs(dir) < kParallel) {
      if (ray.origin[axis] < min[axis] || ray.origin[axis] > max[axis]) return std::nullopt;
      continue;
    }
    const double inv = 1.0 / dir;
    double t0 = (min[axis] - ray.origin[axis]) * inv;
    double t1 = (max[axis] - ray.origin[axis]) * inv;
    if (t0 > t1) std::swap(t0, t1);
    t_near = std::max(t_near, t0);
    t_far = std::min(t_far, t1);
    if (t_near > t_far) return std::nullopt;
  }
  return Span{t_near, t_far};
}

std::optional<double> Box::intersect(const Ray& ray, double max_range) const {
  const auto s = span(ray, max_range);
  if (!s) return std::nullopt;
  return s->entry;
}

bool Box::contains(const Eigen::Vector3d& p, double tolerance) const {
  return (p.array() >= min.array() - tolerance).all() && (p.array() <= max.array() + tolerance).all();
}

Eigen::Vector3d OrientedBox::to_local(const Eigen::Vector3d& p) const {
  return rotate_z(p - center_, cos_yaw_, -sin_yaw_);
}

std::optional<double> OrientedBox::intersect(const Ray& ray, double max_range) const {
  const double c = cos_yaw_, s = -sin_yaw_;
  const Ray local{rotate_z(ray.origin - center_, c, s), rotate_z(ray.direction, c, s)};
  return Box{-half_, half_}.intersect(local, max_range);
}

double OrientedBox::surface_distance(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d q = to_local(p).cwiseAbs() - half_;
  const double outside = q.cwiseMax(0.0).norm();
  const double inside = std::min(q.maxCoeff(), 0.0);
  return std::abs(outside + inside);
}

Polygon::Polygon(std::vector<Eigen::Vector3d> vertices) : vertices_(std::move(vertices)) {
  // Newell's method: robust normal of a planar polygon, length = 2 × area.
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < vertices_.size(); ++i) {
    const Eigen::Vector3d& a = vertices_[i];
    const Eigen::Vector3d& b = vertices_[(i + 1) % vertices_.size()];
    n += a.cross(b);
    centroid += a;
  }
  area_ = 0.5 * n.norm();
  if (area_ <= 0.0 || vertices_.size() < 3) {
    vertices_.clear();
    return;
  }
  normal_ = n.normalized();
  centroid /= static_cast<double>(vertices_.size());
  d_ = normal_.dot(centroid);
  u_ = (vertices_[1] - vertices_[0]).normalized();
  u_ = (u_ - normal_ * normal_.dot(u_)).normalized();
  v_ = normal_.cross(u_);
  local_.reserve(vertices_.size());
  for (const auto& p : vertices_) local_.emplace_back(u_.dot(p), v_.dot(p));
}

bool Polygon::inside_2d(const Eigen::Vector3d& p) const {
  const double x = u_.dot(p), y = v_.dot(p);
  bool inside = false;  // crossing-number test
  for (std::size_t i = 0, j = local_.size() - 1; i < local_.size(); j = i++) {
    const Eigen::Vector2d& a = local_[i];
    const Eigen::Vector2d& b = local_[j];
    if ((a.y() > y) != (b.y() > y)) {
      const double x_cross = a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (x < x_cross) inside = !inside;
    }
  }
  return inside;
}

std::optional<double> Polygon::intersect(const Ray& ray, double max_range) const {
  if (vertices_.empty()) return std::nullopt;
  const double denom = normal_.dot(ray.direction);
  if (std::abs(denom) < kParallel) return std::nullopt;
  const double t = (d_ - normal_.dot(ray.origin)) / denom;
  if (!(t >= 0.0 && t <= max_range)) return std::nullopt;
  if (!inside_2d(ray.origin + t * ray.direction)) return std::nullopt;
  return t;
}

bool Polygon::contains(const Eigen::Vector3d& p, double tolerance) const {
  if (vertices_.empty()) return false;
  return std::abs(normal_.dot(p) - d_) <= tolerance && inside_2d(p);
}

double Polygon::distance(const Eigen::Vector3d& p) const {
  if (vertices_.empty()) return std::numeric_limits<double>::infinity();
  const double off = normal_.dot(p) - d_;
  if (inside_2d(p)) return std::abs(off);
  // Outside the outline: the nearest point lies on an edge.
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < vertices_.size(); ++i) {
    const Eigen::Vector3d& a = vertices_[i];
    const Eigen::Vector3d ab = vertices_[(i + 1) % vertices_.size()] - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (p - (a + t * ab)).norm());
  }
  return best;
}

std::optional<double> Cylinder::intersect(const Ray& ray, double max_range) const {
  double best = std::numeric_limits<double>::infinity();
  const Eigen::Vector2d o = ray.origin.head<2>() - center;
  const Eigen::Vector2d d = ray.direction.head<2>();
  double t0, t1;
  if (solve_quadratic(d.squaredNorm(), 2.0 * o.dot(d), o.squaredNorm() - radius * radius, &t0, &t1)) {
    for (const double t : {t0, t1}) {
      if (t < 0.0) continue;
      const double z = ray.origin.z() + t * ray.direction.z();
      if (z >= z_min && z <= z_max) {
        best = std::min(best, t);
        break;
      }
    }
  }
  if (std::abs(ray.direction.z()) > kParallel) {
    for (const double z : {z_min, z_max}) {
      const double t = (z - ray.origin.z()) / ray.direction.z();
      if (t < 0.0 || t >= best) continue;
      if ((o + t * d).squaredNorm() <= radius * radius) best = t;
    }
  }
  if (best > max_range) return std::nullopt;
  return best;
}

double Cylinder::surface_distance(const Eigen::Vector3d& p) const {
  const double radial = (p.head<2>() - center).norm() - radius;
  const double axial = std::max(z_min - p.z(), p.z() - z_max);
  const Eigen::Vector2d q(radial, axial);
  return std::abs(q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0));
}

std::optional<Span> Ellipsoid::span(const Ray& ray, double max_range) const {
  const Eigen::Vector3d o = (ray.origin - center).cwiseQuotient(radii);
  const Eigen::Vector3d d = ray.direction.cwiseQuotient(radii);
  double t0, t1;
  if (!solve_quadratic(d.squaredNorm(), 2.0 * o.dot(d), o.squaredNorm() - 1.0, &t0, &t1)) return std::nullopt;
  if (t1 < 0.0 || t0 > max_range) return std::nullopt;
  return Span{std::max(t0, 0.0), t1};
}

double Ellipsoid::normalized_radius(const Eigen::Vector3d& p) const {
  return (p - center).cwiseQuotient(radii).norm();
}

std::optional<double> Triangle::intersect(const Ray& ray, double max_range) const {
  const Eigen::Vector3d e1 = b - a, e2 = c - a;
  const Eigen::Vector3d p = ray.direction.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < kParallel) return std::nullopt;
  const double inv = 1.0 / det;
  const Eigen::Vector3d s = ray.origin - a;
  // Barycentric coordinates a hair past the edges still count: a ray through a vertex or an edge
  // the mesh's triangles share hits at least one of them, whatever the rounding.
  constexpr double kEdge = 1e-9;
  const double u = s.dot(p) * inv;
  if (u < -kEdge || u > 1.0 + kEdge) return std::nullopt;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = ray.direction.dot(q) * inv;
  if (v < -kEdge || u + v > 1.0 + kEdge) return std::nullopt;
  const double t = e2.dot(q) * inv;
  if (!(t >= 0.0 && t <= max_range)) return std::nullopt;
  return t;
}

double Triangle::distance(const Eigen::Vector3d& p) const {
  return Polygon({a, b, c}).distance(p);
}

}  // namespace sextant::synth
