#pragma once
// A point cloud in the internal frame (metres): contiguous float xyz, optional intensity and
// per-point time. A cloud
// either owns its points or borrows another's contiguous xyz memory (PointCloud::borrow, for the
// Python module's arrays): reading is the same, the first mutable access copies the borrowed
// points, and a copy of a cloud always owns its points.
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

/// Read-only contiguous points: what PointCloud::points() gives, whether owned or borrowed.
class PointsView {
 public:
  PointsView() = default;
  PointsView(const Eigen::Vector3f* data, std::size_t size) : data_(data), size_(size) {}
  PointsView(const std::vector<Eigen::Vector3f>& points)  // NOLINT: a vector is a view of itself
      : data_(points.data()), size_(points.size()) {}

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const Eigen::Vector3f* data() const { return data_; }
  const Eigen::Vector3f* begin() const { return data_; }
  const Eigen::Vector3f* end() const { return data_ + size_; }
  const Eigen::Vector3f& operator[](std::size_t i) const { return data_[i]; }
  const Eigen::Vector3f& front() const { return data_[0]; }
  const Eigen::Vector3f& back() const { return data_[size_ - 1]; }
  /// Equal sizes and equal points.
  bool operator==(const PointsView& other) const;

 private:
  const Eigen::Vector3f* data_ = nullptr;
  std::size_t size_ = 0;
};

class PointCloud {
 public:
  PointCloud() = default;
  explicit PointCloud(std::vector<Eigen::Vector3f> points) : points_(std::move(points)) {}
  /// A cloud that reads `size` points at `points` without copying them. The memory must outlive
  /// the cloud and stay unchanged while it is read; copies of the cloud own their points.
  static PointCloud borrow(const Eigen::Vector3f* points, std::size_t size);

  PointCloud(const PointCloud& other);
  PointCloud& operator=(const PointCloud& other);
  PointCloud(PointCloud&&) noexcept = default;
  PointCloud& operator=(PointCloud&&) noexcept = default;
  ~PointCloud() = default;

  /// True while the points are another's memory (no mutable access has happened yet).
  bool borrowed() const { return borrowed_ != nullptr; }

  std::size_t size() const { return borrowed_ ? borrowed_size_ : points_.size(); }
  bool empty() const { return size() == 0; }
  void reserve(std::size_t n);

  /// Contiguous xyz triples: `size() * 3` floats starting at `data()`.
  const float* data() const { return empty() ? nullptr : points().front().data(); }
  PointsView points() const {
    return borrowed_ ? PointsView(borrowed_, borrowed_size_) : PointsView(points_);
  }
  /// The owned points for changing them (a borrowed cloud copies its points first).
  std::vector<Eigen::Vector3f>& mutable_points() {
    if (borrowed_) own();
    return points_;
  }
  const Eigen::Vector3f& operator[](std::size_t i) const { return borrowed_ ? borrowed_[i] : points_[i]; }
  Eigen::Vector3f& operator[](std::size_t i) { return mutable_points()[i]; }

  /// Intensity is either empty or has one value per point.
  bool has_intensity() const { return !intensity_.empty(); }
  const std::vector<float>& intensity() const { return intensity_; }
  std::vector<float>& intensity() { return intensity_; }

  /// Per-point time [s] relative to the scan's stamp (Dataset::stamp; negative before it), when the
  /// file has one: either empty or one value per point.
  bool has_time() const { return !time_.empty(); }
  const std::vector<float>& time() const { return time_; }
  /// Gives every point its time: std::invalid_argument unless one value per point (or none, which
  /// removes the times).
  void set_time(std::vector<float> time);

  /// std::logic_error when the cloud has intensity or time (or, with an intensity, has none while it
  /// has points): every point has one, or none has. A cloud with time takes its times by set_time.
  void push_back(const Eigen::Vector3f& p) {
    if (!intensity_.empty() || !time_.empty()) throw_mixed_attributes();
    mutable_points().push_back(p);
  }
  void push_back(const Eigen::Vector3f& p, float intensity);

  /// Axis-aligned bounds; all zero for an empty cloud.
  Bounds bounds() const;
  /// The cloud with every point mapped by T (intensity and time kept).
  PointCloud transformed(const Eigen::Isometry3d& T) const;
  /// The points whose indices are given, in that order (intensity and time kept).
  PointCloud subset(const std::vector<std::size_t>& indices) const;

 private:
  [[noreturn]] static void throw_mixed_attributes();
  void own();  ///< copies the borrowed points into points_ and stops borrowing

  std::vector<Eigen::Vector3f> points_;
  std::vector<float> intensity_;
  std::vector<float> time_;
  const Eigen::Vector3f* borrowed_ = nullptr;  ///< non-null: the points are these, not points_
  std::size_t borrowed_size_ = 0;
};

/// Drops points with a NaN or Inf coordinate (or intensity, or time); returns how many were dropped.
std::size_t remove_non_finite(PointCloud& cloud);

}  // namespace sextant
