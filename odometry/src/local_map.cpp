#include "sextant/odometry/local_map.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace sextant {
namespace {

/// A voxel index packed into 64 bits (21 bits per axis, offset so negative indices fit); never
/// kNoVoxel (its top bit is clear).
std::uint64_t voxel_key(const Eigen::Vector3f& p, double inverse_edge) {
  constexpr std::int64_t kOffset = std::int64_t{1} << 20;
  constexpr std::uint64_t kMask = (std::uint64_t{1} << 21) - 1;
  std::uint64_t key = 0;
  for (int a = 0; a < 3; ++a) {
    // Clamped so that the conversion is defined for any finite coordinate (the 21 bits wrap anyway).
    const double scaled = std::clamp(static_cast<double>(p[a]) * inverse_edge, -1e15, 1e15);
    auto index = static_cast<std::int64_t>(scaled);
    if (static_cast<double>(index) > scaled) --index;  // floor, without a libm call per coordinate
    key = (key << 21) | (static_cast<std::uint64_t>(index + kOffset) & kMask);
  }
  return key;
}

constexpr std::uint64_t kNoVoxel = ~std::uint64_t{0};

/// Voxel key → index of its sums: open addressing with linear probing in a power-of-two table kept
/// at most half full (a node per voxel, as std::unordered_map allocates, took most of the filter's time).
class VoxelSlots {
 public:
  explicit VoxelSlots(std::size_t expected) { resize(std::max<std::size_t>(64, 2 * expected)); }
  /// The slot of `key`, and whether it was new (then `next` became its slot).
  std::pair<std::uint32_t, bool> find_or_add(std::uint64_t key, std::uint32_t next) {
    if (2 * (size_ + 1) > keys_.size()) grow();
    std::size_t i = bucket(key);
    while (keys_[i] != kNoVoxel) {
      if (keys_[i] == key) return {slots_[i], false};
      i = (i + 1) & mask_;
    }
    keys_[i] = key;
    slots_[i] = next;
    ++size_;
    return {next, true};
  }

 private:
  std::size_t bucket(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ull) >> shift_);  // Fibonacci hashing
  }
  void resize(std::size_t at_least) {
    std::size_t capacity = 64;
    int bits = 6;
    while (capacity < at_least) capacity *= 2, ++bits;
    keys_.assign(capacity, kNoVoxel);
    slots_.assign(capacity, 0);
    mask_ = capacity - 1;
    shift_ = 64 - bits;
  }
  void grow() {
    const std::vector<std::uint64_t> keys = std::move(keys_);
    const std::vector<std::uint32_t> slots = std::move(slots_);
    resize(2 * keys.size());
    for (std::size_t j = 0; j < keys.size(); ++j) {
      if (keys[j] == kNoVoxel) continue;
      std::size_t i = bucket(keys[j]);
      while (keys_[i] != kNoVoxel) i = (i + 1) & mask_;
      keys_[i] = keys[j];
      slots_[i] = slots[j];
    }
  }

  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> slots_;
  std::size_t mask_ = 0, size_ = 0;
  int shift_ = 0;
};

}  // namespace

PointCloud voxel_downsample(const PointCloud& cloud, double voxel) {
  if (!(voxel > 0.0) || cloud.empty()) return cloud;
  const double inverse_edge = 1.0 / voxel;
  // A local map of overlapping scans holds a few points per voxel: a quarter of the points is the
  // table's first guess (it grows when needed).
  VoxelSlots slots(cloud.size() / 4);
  std::vector<Eigen::Vector4d> sums;  // Σx, Σy, Σz, count per voxel, in the order of first points
  sums.reserve(cloud.size() / 4);
  for (const Eigen::Vector3f& p : cloud.points()) {
    const auto [slot, fresh] =
        slots.find_or_add(voxel_key(p, inverse_edge), static_cast<std::uint32_t>(sums.size()));
    if (fresh) sums.emplace_back(Eigen::Vector4d::Zero());
    Eigen::Vector4d& s = sums[slot];
    s.head<3>() += p.cast<double>();
    s(3) += 1.0;
  }
  PointCloud out;
  out.reserve(sums.size());
  for (const Eigen::Vector4d& s : sums) out.push_back((s.head<3>() / s(3)).cast<float>());
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
