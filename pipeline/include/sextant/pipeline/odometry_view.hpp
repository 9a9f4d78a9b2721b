#pragma once
// The view of an odometry run (eval/run_view.hpp) for every face: `sextant odometry --view run.html`
// and sextant.odometry(..., view="run.html"). Its map is the run's own (RunMap, the one --map-out
// writes), coarsened until a browser draws it at once.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/dataset.hpp"
#include "sextant/core/point_cloud.hpp"
#include "sextant/eval/run_view.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/pipeline/run_map.hpp"

namespace sextant {

/// The run's map as its view draws it.
struct RunViewMap {
  PointCloud points;           ///< world frame, one centroid per voxel
  double voxel = 0.0;          ///< the voxel edge it ended with [m]
  std::size_t scans_read = 0;  ///< the scans in the map
};

/// The run's map (run_map.hpp) with at most `max_points` points: its voxel edge doubled, the voxels'
/// centroids merged into the coarser voxels' centroids, until they are few enough.
RunViewMap run_view_map(const RunMap& map, std::size_t max_points = kRunViewMaxMapPoints);

/// The view of a run over scans first … first + poses.size() − 1: `map` (world frame), `poses` (the
/// trajectory written: the chain, or the loop-closed one), the ground truth `truth` when known, and one
/// record per step of `result` (drawn at the scan it registers, with the dataset's time of that scan,
/// its trust, recovery and reason, and its error against the truth as steps.csv's error_m / error_deg).
RunView odometry_run_view(const Dataset& dataset, std::size_t first, const OdometryResult& result,
                          const std::vector<Eigen::Isometry3d>& poses,
                          const std::optional<std::vector<Eigen::Isometry3d>>& truth, const RunViewMap& map,
                          const std::string& title);

/// run_view_map of the run's map, then odometry_run_view, written atomically to `path`.
void write_odometry_view(const std::filesystem::path& path, const Dataset& dataset, std::size_t first,
                         const OdometryResult& result, const std::vector<Eigen::Isometry3d>& poses,
                         const std::optional<std::vector<Eigen::Isometry3d>>& truth, const RunMap& map,
                         const std::string& title);

}  // namespace sextant
