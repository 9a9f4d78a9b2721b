#include "sextant/pipeline/run_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <utility>

#include "sextant/core/error.hpp"
#include "sextant/matchers/registration_centre.hpp"

namespace sextant {
namespace {

/// ⌊x⌋ as a voxel index, or false when x is not finite or ⌊x⌋ leaves the 32-bit range.
bool voxel_index(double x, int* index) {
  const double f = std::floor(x);
  if (!(f >= static_cast<double>(std::numeric_limits<int>::min()) &&
        f <= static_cast<double>(std::numeric_limits<int>::max())))
    return false;
  *index = static_cast<int>(f);
  return true;
}

}  // namespace

std::string map_voxel_problem(double voxel_size) {
  if (std::isfinite(voxel_size) && voxel_size > 0.0) return {};
  std::ostringstream text;
  text << "must be a finite number > 0 metres, got " << voxel_size;
  return text.str();
}

RunMap::RunMap(double voxel_size) : voxel_size_(voxel_size), inverse_size_(1.0 / voxel_size) {
  if (const std::string problem = map_voxel_problem(voxel_size); !problem.empty())
    throw InputError("map voxel", "", "the voxel " + problem);
  slots_.assign(64, 0);
}

std::size_t RunMap::bucket(const Eigen::Vector3i& index) const {
  const auto bits = [](int i) { return static_cast<std::uint64_t>(static_cast<std::uint32_t>(i)); };
  const std::uint64_t h = bits(index.x()) * 0x9e3779b97f4a7c15ull ^ bits(index.y()) * 0xc2b2ae3d27d4eb4full ^
                          bits(index.z()) * 0x165667b19e3779f9ull;
  return static_cast<std::size_t>((h ^ (h >> 32)) & (slots_.size() - 1));
}

void RunMap::grow() {
  slots_.assign(2 * slots_.size(), 0);
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t v = 0; v < size_; ++v) {
    std::size_t i = bucket(voxel(v).index);
    while (slots_[i] != 0) i = (i + 1) & mask;
    slots_[i] = static_cast<std::uint32_t>(v + 1);
  }
}

RunMap::Voxel& RunMap::voxel_at(const Eigen::Vector3i& index) {
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = bucket(index);
  while (slots_[i] != 0) {
    Voxel& v = voxel(slots_[i] - 1);
    if (v.index == index) return v;
    i = (i + 1) & mask;
  }
  if (size_ >= std::numeric_limits<std::uint32_t>::max() - 1)
    throw InputError("map", "", "more than 4,294,967,294 occupied voxels: choose a larger voxel");
  if ((size_ >> kBlockBits) == blocks_.size()) blocks_.emplace_back().reserve(kBlockMask + 1);
  blocks_.back().push_back(Voxel{index});
  ++size_;
  slots_[i] = static_cast<std::uint32_t>(size_);
  // Kept at most half full, so that a probe ends after a few slots.
  if (2 * size_ > slots_.size()) grow();
  return blocks_.back().back();
}

void RunMap::add(const PointCloud& scan, const Eigen::Isometry3d& world_from_scan) {
  ++scans_;
  intensity_ = intensity_ && scan.has_intensity();
  const std::vector<float>& intensity = scan.intensity();
  for (std::size_t j = 0; j < scan.size(); ++j) {
    const Eigen::Vector3d p = world_from_scan * scan[j].cast<double>();
    Eigen::Vector3i index;
    if (!(voxel_index(p.x() * inverse_size_, &index.x()) && voxel_index(p.y() * inverse_size_, &index.y()) &&
          voxel_index(p.z() * inverse_size_, &index.z()))) {
      ++skipped_points_;
      continue;
    }
    Voxel& v = voxel_at(index);
    ++v.count;
    v.sum += p;
    if (intensity_) v.intensity_sum += static_cast<double>(intensity[j]);
    ++points_added_;
  }
}

PointCloud RunMap::cloud() const {
  PointCloud out;
  out.reserve(size_);
  const bool intensity = has_intensity();
  if (intensity) out.intensity().reserve(size_);
  for (std::size_t k = 0; k < size_; ++k) {
    const Voxel& v = voxel(k);
    const double n = static_cast<double>(v.count);
    const Eigen::Vector3f centroid = (v.sum / n).cast<float>();
    if (intensity)
      out.push_back(centroid, static_cast<float>(v.intensity_sum / n));
    else
      out.push_back(centroid);
  }
  return out;
}

double scan_median_range(const PointCloud& scan) {
  if (scan.empty()) return 0.0;
  const Eigen::Vector3f centre = registration_centre(scan).cast<float>();
  std::vector<float> ranges;
  ranges.reserve(scan.size());
  for (const Eigen::Vector3f& p : scan.points()) ranges.push_back((p - centre).norm());
  const auto middle = ranges.begin() + static_cast<std::ptrdiff_t>(ranges.size() / 2);
  std::nth_element(ranges.begin(), middle, ranges.end());
  return static_cast<double>(*middle);
}

double default_map_voxel_size(const PointCloud& first_scan) {
  constexpr double kFloor = 0.01;  // [m]
  const double size = scan_median_range(first_scan) / 100.0;
  if (!(size > kFloor)) return kFloor;
  // 1, 2 or 5 × 10^e, the nearest on a log scale (the boundaries are the geometric means).
  const double decade = std::pow(10.0, std::floor(std::log10(size)));
  const double m = size / decade;
  const double nice = m < std::sqrt(2.0) ? 1.0 : m < std::sqrt(10.0) ? 2.0 : m < std::sqrt(50.0) ? 5.0 : 10.0;
  return nice * decade;
}

}  // namespace sextant
