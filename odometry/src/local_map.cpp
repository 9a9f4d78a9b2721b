#include "sextant/odometry/local_map.hpp"

#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace sextant {
namespace {

/// A voxel index packed into 64 bits (21 bits per axis, offset so negative indices fit).
std::uint64_t voxel_key(const Eigen::Vector3f& p, double inverse_edge) {
  constexpr std::int64_t kOffset = std::int64_t{1} << 20;
  constexpr std::uint64_t kMask = (std::uint64_t{1} << 21) - 1;
  std::uint64_t key = 0;
  for (int a = 0; a < 3; ++a) {
    const auto index = static_cast<std::int64_t>(std::floor(static_cast<double>(p[a]) * inverse_edge));
    key = (key << 21) | (static_cast<std::uint64_t>(index + kOffset) & kMask);
  }
  return key;
}

}  // namespace

PointCloud voxel_downsample(const PointCloud& cloud, double voxel) {
  if (!(voxel > 0.0) || cloud.empty()) return cloud;
  const double inverse_edge = 1.0 / voxel;
  std::unordered_map<std::uint64_t, std::size_t> slot;  // voxel → index into sums
  std::vector<Eigen::Vector3d> sums;
  std::vector<double> counts;
  slot.reserve(cloud.size() / 4);
  for (const Eigen::Vector3f& p : cloud.points()) {
    const auto [it, inserted] = slot.emplace(voxel_key(p, inverse_edge), sums.size());
    if (inserted) {
      sums.emplace_back(Eigen::Vector3d::Zero());
      counts.push_back(0.0);
    }
    sums[it->second] += p.cast<double>();
    counts[it->second] += 1.0;
  }
  PointCloud out;
  out.reserve(sums.size());
  for (std::size_t i = 0; i < sums.size(); ++i) out.push_back((sums[i] / counts[i]).cast<float>());
  return out;
}

PointCloud merge_local_map(const std::vector<const PointCloud*>& clouds,
                           const std::vector<Eigen::Isometry3d>& poses, std::size_t max_points,
                           double voxel) {
  std::size_t total = 0;
  for (const PointCloud* c : clouds) total += c->size();
  PointCloud map;
  map.reserve(total);
  for (std::size_t j = 0; j < clouds.size(); ++j) {
    const Eigen::Isometry3f T = poses[j].cast<float>();
    for (const Eigen::Vector3f& p : clouds[j]->points()) map.push_back(T * p);
  }
  if (map.size() > max_points) return voxel_downsample(map, voxel);
  return map;
}

}  // namespace sextant
