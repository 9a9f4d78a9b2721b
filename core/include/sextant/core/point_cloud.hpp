#pragma once
// A point cloud in the internal frame (metres): contiguous float xyz, optional intensity.
#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sextant {

struct Bounds {
  Eigen::Vector3f min = Eigen::Vector3f::Constant(0.0f);
  Eigen::Vector3f max = Eigen::Vector3f::Constant(0.0f);
  Eigen::Vector3f extent() const { return max - min; }
  double volume() const;
};

class PointCloud {
 public:
  PointCloud() = default;
  explicit PointCloud(std::vector<Eigen::Vector3f> points) : points_(std::move(points)) {}

  std::size_t size() const { return points_.size(); }
  bool empty() const { return points_.empty(); }
  void reserve(std::size_t n);

  /// Contiguous xyz triples: `size() * 3` floats starting at `data()`.
  const float* data() const { return points_.empty() ? nullptr : points_.front().data(); }
  const std::vector<Eigen::Vector3f>& points() const { return points_; }
  std::vector<Eigen::Vector3f>& points() { return points_; }
  const Eigen::Vector3f& operator[](std::size_t i) const { return points_[i]; }
  Eigen::Vector3f& operator[](std::size_t i) { return points_[i]; }

  /// Intensity is either empty or has one value per point.
  bool has_intensity() const { return !intensity_.empty(); }
  const std::vector<float>& intensity() const { return intensity_; }
  std::vector<float>& intensity() { return intensity_; }

  void push_back(const Eigen::Vector3f& p) { points_.push_back(p); }
  void push_back(const Eigen::Vector3f& p, float intensity);

  /// Axis-aligned bounds; all zero for an empty cloud.
  Bounds bounds() const;
  /// The cloud with every point mapped by T (intensity kept).
  PointCloud transformed(const Eigen::Isometry3d& T) const;
  /// The points whose indices are given, in that order (intensity kept).
  PointCloud subset(const std::vector<std::size_t>& indices) const;

 private:
  std::vector<Eigen::Vector3f> points_;
  std::vector<float> intensity_;
};

/// Drops points with a NaN or Inf coordinate (or intensity); returns how many were dropped.
std::size_t remove_non_finite(PointCloud& cloud);

}  // namespace sextant
