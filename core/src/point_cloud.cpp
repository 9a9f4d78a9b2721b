#include "sextant/core/point_cloud.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace sextant {

double Bounds::volume() const {
  const Eigen::Vector3d e = extent().cast<double>();
  return e.x() * e.y() * e.z();
}

bool PointsView::operator==(const PointsView& other) const {
  return size_ == other.size_ && std::equal(begin(), end(), other.begin());
}

PointCloud PointCloud::borrow(const Eigen::Vector3f* points, std::size_t size) {
  PointCloud cloud;
  if (size == 0) return cloud;
  cloud.borrowed_ = points;
  cloud.borrowed_size_ = size;
  return cloud;
}

PointCloud::PointCloud(const PointCloud& other)
    : points_(other.points().begin(), other.points().end()),
      intensity_(other.intensity_),
      time_(other.time_) {}

PointCloud& PointCloud::operator=(const PointCloud& other) {
  if (this == &other) return *this;
  const PointsView source = other.points();
  points_.assign(source.begin(), source.end());
  intensity_ = other.intensity_;
  time_ = other.time_;
  borrowed_ = nullptr;
  borrowed_size_ = 0;
  return *this;
}

void PointCloud::own() {
  points_.assign(borrowed_, borrowed_ + borrowed_size_);
  borrowed_ = nullptr;
  borrowed_size_ = 0;
}

void PointCloud::reserve(std::size_t n) {
  mutable_points().reserve(n);
  if (has_intensity()) intensity_.reserve(n);
}

void PointCloud::set_time(std::vector<float> time) {
  if (!time.empty() && time.size() != size())
    throw std::invalid_argument("PointCloud::set_time: " + std::to_string(time.size()) + " times for " +
                                std::to_string(size()) + " points");
  time_ = std::move(time);
}

void PointCloud::throw_mixed_attributes() {
  throw std::logic_error(
      "PointCloud::push_back: a point without intensity or time in a cloud whose points have them");
}

void PointCloud::push_back(const Eigen::Vector3f& p, float intensity) {
  if (!time_.empty()) throw_mixed_attributes();
  if (intensity_.size() != size()) {
    throw std::logic_error("PointCloud::push_back: mixing points with and without intensity");
  }
  mutable_points().push_back(p);
  intensity_.push_back(intensity);
}

Bounds PointCloud::bounds() const {
  Bounds b;
  const PointsView points = this->points();
  if (points.empty()) return b;
  // The coordinates as one float array, four points (12 floats) at a time into 12 running minima and
  // maxima, slot j holding axis j % 3. Every update is std::min(m, x) = x < m ? x : m (a NaN
  // coordinate never replaces a number; _mm_min_ps(x, m) is the same), so the result is the same as
  // one point at a time.
  const float* c = points.data()->data();
  const std::size_t n = points.size();
  alignas(16) float lo[12], hi[12];
  for (int j = 0; j < 12; ++j) lo[j] = hi[j] = c[j % 3];
  std::size_t i = 0;
#if defined(__SSE2__)
  __m128 lo4[3], hi4[3];
  for (int k = 0; k < 3; ++k) lo4[k] = hi4[k] = _mm_load_ps(lo + 4 * k);
  for (; i + 4 <= n; i += 4, c += 12)
    for (int k = 0; k < 3; ++k) {
      const __m128 x = _mm_loadu_ps(c + 4 * k);
      lo4[k] = _mm_min_ps(x, lo4[k]);
      hi4[k] = _mm_max_ps(x, hi4[k]);
    }
  for (int k = 0; k < 3; ++k) _mm_store_ps(lo + 4 * k, lo4[k]), _mm_store_ps(hi + 4 * k, hi4[k]);
#else
  for (; i + 4 <= n; i += 4, c += 12)
    for (int j = 0; j < 12; ++j) lo[j] = std::min(lo[j], c[j]), hi[j] = std::max(hi[j], c[j]);
#endif
  for (int a = 0; a < 3; ++a) {
    b.min(a) = lo[a], b.max(a) = hi[a];
    for (int j = a + 3; j < 12; j += 3)
      b.min(a) = std::min(b.min(a), lo[j]), b.max(a) = std::max(b.max(a), hi[j]);
  }
  for (; i < n; ++i, c += 3)
    for (int a = 0; a < 3; ++a) b.min(a) = std::min(b.min(a), c[a]), b.max(a) = std::max(b.max(a), c[a]);
  return b;
}

PointCloud PointCloud::transformed(const Eigen::Isometry3d& T) const {
  const Eigen::Isometry3f Tf = T.cast<float>();
  PointCloud out;
  out.points_.reserve(size());
  for (const auto& p : points()) out.points_.push_back(Tf * p);
  out.intensity_ = intensity_;
  out.time_ = time_;
  return out;
}

PointCloud PointCloud::subset(const std::vector<std::size_t>& indices) const {
  PointCloud out;
  out.points_.reserve(indices.size());
  const PointsView points = this->points();
  for (std::size_t i : indices) {
    if (i >= points.size()) throw std::out_of_range("PointCloud::subset: index beyond the cloud");
    out.points_.push_back(points[i]);
  }
  if (has_intensity()) {
    out.intensity_.reserve(indices.size());
    for (std::size_t i : indices) out.intensity_.push_back(intensity_[i]);
  }
  if (has_time()) {
    out.time_.reserve(indices.size());
    for (std::size_t i : indices) out.time_.push_back(time_[i]);
  }
  return out;
}

std::size_t remove_non_finite(PointCloud& cloud) {
  const PointCloud& read = cloud;
  const auto finite = [](float v) { return std::isfinite(v); };
  const bool all_finite = std::all_of(read.points().begin(), read.points().end(),
                                      [](const Eigen::Vector3f& p) { return p.allFinite(); }) &&
                          std::all_of(read.intensity().begin(), read.intensity().end(), finite) &&
                          std::all_of(read.time().begin(), read.time().end(), finite);
  if (all_finite) return 0;  // a borrowed cloud stays borrowed
  auto& pts = cloud.mutable_points();
  auto& inten = cloud.intensity();
  std::vector<float> time = cloud.time();
  const bool with_intensity = cloud.has_intensity();
  const bool with_time = cloud.has_time();
  std::size_t kept = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const bool ok = pts[i].allFinite() && (!with_intensity || std::isfinite(inten[i])) &&
                    (!with_time || std::isfinite(time[i]));
    if (!ok) continue;
    pts[kept] = pts[i];
    if (with_intensity) inten[kept] = inten[i];
    if (with_time) time[kept] = time[i];
    ++kept;
  }
  const std::size_t dropped = pts.size() - kept;
  pts.resize(kept);
  if (with_intensity) inten.resize(kept);
  time.resize(with_time ? kept : 0);
  cloud.set_time(std::move(time));
  return dropped;
}

}  // namespace sextant
