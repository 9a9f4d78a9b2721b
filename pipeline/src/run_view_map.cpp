// The map of an odometry run's view (odometry_view.hpp): an adaptive voxel grid of centroids over the
// registered scans, read again one at a time.
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "sextant/pipeline/odometry_view.hpp"

namespace sextant {
namespace {

using VoxelKey = std::array<std::int64_t, 3>;

struct VoxelKeyHash {
  std::size_t operator()(const VoxelKey& k) const {
    return static_cast<std::size_t>(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
  }
};

/// The points of a voxel: their sum and count (the centroid is sum / count).
struct VoxelSum {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::size_t count = 0;
};

class VoxelGrid {
 public:
  VoxelGrid(double voxel, std::size_t max_voxels)
      : voxel_(voxel), max_(std::max<std::size_t>(1, max_voxels)) {}

  void add(const Eigen::Vector3d& p, std::size_t count = 1, const Eigen::Vector3d* sum = nullptr) {
    VoxelSum& v = voxels_[key(p)];
    v.sum += sum ? *sum : p;
    v.count += count;
  }
  /// Doubles the voxel edge while there are more voxels than allowed.
  void bound() {
    while (voxels_.size() > max_) {
      voxel_ *= 2.0;
      std::unordered_map<VoxelKey, VoxelSum, VoxelKeyHash> old;
      old.swap(voxels_);
      for (const auto& [k, v] : old) {
        const Eigen::Vector3d centroid = v.sum / static_cast<double>(v.count);
        add(centroid, v.count, &v.sum);
      }
    }
  }
  PointCloud centroids() const {
    PointCloud out;
    out.reserve(voxels_.size());
    for (const auto& [k, v] : voxels_) out.push_back((v.sum / static_cast<double>(v.count)).cast<float>());
    return out;
  }
  double voxel() const { return voxel_; }

 private:
  VoxelKey key(const Eigen::Vector3d& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / voxel_)),
            static_cast<std::int64_t>(std::floor(p.y() / voxel_)),
            static_cast<std::int64_t>(std::floor(p.z() / voxel_))};
  }
  double voxel_;
  std::size_t max_;
  std::unordered_map<VoxelKey, VoxelSum, VoxelKeyHash> voxels_;
};

}  // namespace

RunViewMap run_view_map(const Dataset& dataset, std::size_t first,
                        const std::vector<Eigen::Isometry3d>& poses, double min_range, std::size_t max_points,
                        std::size_t max_scans, double voxel) {
  VoxelGrid grid(voxel > 0.0 ? voxel : 0.05, max_points);
  RunViewMap out;
  const std::size_t n = poses.size();
  const std::size_t reads = std::min(n, std::max<std::size_t>(1, max_scans));
  std::size_t last = n;  // the scan read last (evenly spaced indices can repeat when reads ≈ n)
  for (std::size_t r = 0; r < reads; ++r) {
    const std::size_t i = reads == 1 ? 0 : r * (n - 1) / (reads - 1);
    if (i == last || !poses[i].matrix().allFinite()) continue;
    last = i;
    const PointCloud scan = load_sequence_scan(dataset, first + i, min_range);
    for (const Eigen::Vector3f& p : scan.points())
      if (p.allFinite()) grid.add(poses[i] * p.cast<double>());
    grid.bound();
    ++out.scans_read;
  }
  out.points = grid.centroids();
  out.voxel = grid.voxel();
  return out;
}

}  // namespace sextant
