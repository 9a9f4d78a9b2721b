#pragma once
// The map of an odometry run: every registered scan moved into the world by its pose and
// voxel-filtered into one cloud, one point per occupied cubic voxel (what `sextant odometry --map-out`
// writes, what sextant.odometry(build_map=True) returns, what the run's view draws).
//
//   RunMap map(default_map_voxel_size(first_scan));
//   map.add(scan, world_from_scan);   // for each scan; no scan is kept
//   const PointCloud cloud = map.cloud();
//
// Each voxel's point is the centroid of every point that fell into it, from every scan: sensor noise
// and small pose differences between the scans that saw a surface average out, as in the local map
// (local_map.hpp), and the result does not depend on which scan saw the voxel first. Memory grows with
// the occupied voxels (56–64 bytes each), never with the number of scans.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"

namespace sextant {

class RunMap {
 public:
  /// InputError("map voxel") unless `voxel_size` [m] is finite and > 0 (map_voxel_problem).
  explicit RunMap(double voxel_size);

  /// Adds every point of `scan` (its sensor frame) mapped by `world_from_scan`. Intensity is kept while
  /// every scan added has it; a scan without it drops it from the map. Points whose voxel index leaves
  /// the 32-bit range (or that are not finite) are not added, and counted (skipped_points).
  void add(const PointCloud& scan, const Eigen::Isometry3d& world_from_scan);

  /// One point per occupied voxel, the centroid of its points (and the mean of their intensities), in
  /// the order the voxels were first hit (deterministic for a given order of adds).
  PointCloud cloud() const;
  /// Occupied voxels: the points cloud() returns.
  std::size_t size() const { return size_; }
  double voxel_size() const { return voxel_size_; }

  /// Whether cloud() has intensity: a scan was added, and every scan added had it.
  bool has_intensity() const { return intensity_ && scans_ > 0; }
  /// Scans added, and points added and skipped over them.
  std::size_t scans() const { return scans_; }
  std::size_t points_added() const { return points_added_; }
  std::size_t skipped_points() const { return skipped_points_; }

 private:
  struct Voxel {
    Eigen::Vector3i index;
    std::uint32_t count = 0;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();  ///< Σ world points
    double intensity_sum = 0.0;
  };
  /// Voxels are kept in blocks of 2^kBlockBits, never moved once added: memory is the voxels' (48 bytes
  /// each, and 4 bytes for each of 2–4 slots), without a doubling vector's spare half or its copy.
  static constexpr std::size_t kBlockBits = 14;
  static constexpr std::size_t kBlockMask = (std::size_t{1} << kBlockBits) - 1;
  Voxel& voxel(std::size_t v) { return blocks_[v >> kBlockBits][v & kBlockMask]; }
  const Voxel& voxel(std::size_t v) const { return blocks_[v >> kBlockBits][v & kBlockMask]; }
  /// The voxel at `index`, added when new.
  Voxel& voxel_at(const Eigen::Vector3i& index);
  std::size_t bucket(const Eigen::Vector3i& index) const;
  void grow();

  double voxel_size_;
  double inverse_size_;
  std::vector<std::vector<Voxel>> blocks_;  ///< the voxels, in the order they were first hit
  std::size_t size_ = 0;
  std::vector<std::uint32_t> slots_;  ///< open addressing: voxel number + 1, 0 = empty; ≤ half full
  bool intensity_ = true;             ///< every scan so far had intensity
  std::size_t scans_ = 0, points_added_ = 0, skipped_points_ = 0;
};

/// Empty when `voxel_size` [m] can be a map's voxel (finite, > 0), else what is wrong ("must be …"),
/// for the faces to name their argument.
std::string map_voxel_problem(double voxel_size);

/// The median distance of the scan's points from where its sensor stood (the origin of its frame; for
/// a scan not in its sensor's frame, the point it is registered about, registration_centre.hpp) [m];
/// 0 for an empty scan.
double scan_median_range(const PointCloud& scan);

/// The map's voxel when none is given: 1/100 of the first scan's median range, rounded to 1, 2 or 5
/// times a power of ten (nearest on a log scale), at least 1 cm. 1/100 of the range is a voxel seen
/// under 0.57°, about a spinning lidar's spacing between rings there: a map about as dense as a scan
/// where most of its points lie, on any scale (MulRan's car 0.1–0.2 m, a hand-held sensor indoors a few
/// cm).
double default_map_voxel_size(const PointCloud& first_scan);

}  // namespace sextant
