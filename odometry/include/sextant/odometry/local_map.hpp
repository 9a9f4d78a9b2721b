#pragma once
// The local map of scan-to-map odometry: the last k scans moved into one frame, voxel-filtered
// (one centroid per occupied voxel) when it grows large.
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"

namespace sextant {

/// One point per occupied cubic voxel of edge `voxel` [m]: the centroid of its points, in the order
/// of the voxels' first points (deterministic). Intensity is dropped. voxel ≤ 0 returns the cloud.
PointCloud voxel_downsample(const PointCloud& cloud, double voxel);

/// The union of clouds[j] mapped by poses[j] (frame ← cloud j), voxel-filtered with `voxel` when it
/// holds more than `max_points` points.
PointCloud merge_local_map(const std::vector<const PointCloud*>& clouds,
                           const std::vector<Eigen::Isometry3d>& poses, std::size_t max_points, double voxel);

}  // namespace sextant
