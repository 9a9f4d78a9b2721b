#pragma once
// How densely a scan samples its surfaces (issue 62, item 3): the distance from a point to its nearest
// neighbour, measured on the scan itself, so that sizes which must hold a number of points (a precision
// cell's covariance) follow the sensor and its downsampling instead of a constant tuned on 64-ring
// scans. A spinning 64-ring lidar's raw scan lies 0.1–0.2 m apart at 20 m; a voxel-downsampled
// keyframe as far apart as its voxels; a 4k-point solid-state scan farther.
//
//   const PointSpacing s = measure_point_spacing(scan);
//   s.median;  // [m], 0 when the scan has fewer than two finite points
#include <cstddef>

#include "sextant/core/point_cloud.hpp"

namespace sextant {

struct PointSpacing {
  double median = 0.0;      ///< median distance from a point to its nearest other point [m]
  std::size_t queried = 0;  ///< points whose nearest neighbour was measured
  std::size_t finite = 0;   ///< finite points of the scan
};

/// Queries at most `max_queries` points, evenly spread over the scan's storage order (every k-th
/// finite point), against all its finite points; duplicates (distance 0) count as 0. Deterministic.
PointSpacing measure_point_spacing(const PointCloud& scan, std::size_t max_queries = 2000);

}  // namespace sextant
