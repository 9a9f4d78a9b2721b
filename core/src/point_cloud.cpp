#include "sextant/core/point_cloud.hpp"

#include <cmath>
#include <stdexcept>

namespace sextant {

double Bounds::volume() const {
  const Eigen::Vector3d e = extent().cast<double>();
  return e.x() * e.y() * e.z();
}

void PointCloud::reserve(std::size_t n) {
  points_.reserve(n);
  if (has_intensity()) intensity_.reserve(n);
}

void PointCloud::push_back(const Eigen::Vector3f& p, float intensity) {
  if (intensity_.size() != points_.size()) {
    throw std::logic_error("PointCloud::push_back: mixing points with and without intensity");
  }
  points_.push_back(p);
  intensity_.push_back(intensity);
}

Bounds PointCloud::bounds() const {
  Bounds b;
  if (points_.empty()) return b;
  b.min = b.max = points_.front();
  for (const auto& p : points_) {
    b.min = b.min.cwiseMin(p);
    b.max = b.max.cwiseMax(p);
  }
  return b;
}

PointCloud PointCloud::transformed(const Eigen::Isometry3d& T) const {
  const Eigen::Isometry3f Tf = T.cast<float>();
  PointCloud out;
  out.points_.reserve(points_.size());
  for (const auto& p : points_) out.points_.push_back(Tf * p);
  out.intensity_ = intensity_;
  return out;
}

PointCloud PointCloud::subset(const std::vector<std::size_t>& indices) const {
  PointCloud out;
  out.points_.reserve(indices.size());
  for (std::size_t i : indices) out.points_.push_back(points_.at(i));
  if (has_intensity()) {
    out.intensity_.reserve(indices.size());
    for (std::size_t i : indices) out.intensity_.push_back(intensity_[i]);
  }
  return out;
}

std::size_t remove_non_finite(PointCloud& cloud) {
  auto& pts = cloud.points();
  auto& inten = cloud.intensity();
  const bool with_intensity = cloud.has_intensity();
  std::size_t kept = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const bool finite = pts[i].allFinite() && (!with_intensity || std::isfinite(inten[i]));
    if (!finite) continue;
    pts[kept] = pts[i];
    if (with_intensity) inten[kept] = inten[i];
    ++kept;
  }
  const std::size_t dropped = pts.size() - kept;
  pts.resize(kept);
  if (with_intensity) inten.resize(kept);
  return dropped;
}

}  // namespace sextant
