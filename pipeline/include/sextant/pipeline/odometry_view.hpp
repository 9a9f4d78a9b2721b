#pragma once
// The view of an odometry run (eval/run_view.hpp) for every face: `sextant odometry --view run.html`
// and sextant.odometry(..., view="run.html"). Its map is made by run_view_map until the run's own map
// (RunMap, issue 63's --map-out) takes its place: the registered scans read again from the dataset,
// one at a time, put in the world by the final poses and voxel-filtered with bounded memory.
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

namespace sextant {

/// What run_view_map made.
struct RunViewMap {
  PointCloud points;           ///< world frame, one centroid per voxel
  double voxel = 0.0;          ///< the voxel edge it ended with [m]
  std::size_t scans_read = 0;  ///< of poses.size()
};

/// Scans first … first + poses.size() − 1 of `dataset` (at most `max_scans` of them, evenly spaced, the
/// first and the last among them), each without the points closer than `min_range` (as the chain
/// registered it), put in the world by poses[i] and voxel-filtered into at most `max_points` centroids:
/// the voxel edge starts at `voxel` and doubles, merging the voxels' sums, whenever there are more. Memory
/// holds one scan and the voxels. Non-finite poses are skipped.
RunViewMap run_view_map(const Dataset& dataset, std::size_t first,
                        const std::vector<Eigen::Isometry3d>& poses, double min_range,
                        std::size_t max_points = kRunViewMaxMapPoints, std::size_t max_scans = 1000,
                        double voxel = 0.05);

/// The view of a run over scans first … first + poses.size() − 1: `map` (world frame), `poses` (the
/// trajectory written: the chain, or the loop-closed one), the ground truth `truth` when known, and one
/// record per step of `result` (drawn at the scan it registers, with the dataset's time of that scan,
/// its trust, recovery and reason, and its error against the truth as steps.csv's error_m / error_deg).
RunView odometry_run_view(const Dataset& dataset, std::size_t first, const OdometryResult& result,
                          const std::vector<Eigen::Isometry3d>& poses,
                          const std::optional<std::vector<Eigen::Isometry3d>>& truth, const RunViewMap& map,
                          const std::string& title);

/// run_view_map with the run's min_range, then odometry_run_view, written atomically to `path`.
void write_odometry_view(const std::filesystem::path& path, const Dataset& dataset, std::size_t first,
                         const OdometryResult& result, const std::vector<Eigen::Isometry3d>& poses,
                         const std::optional<std::vector<Eigen::Isometry3d>>& truth, double min_range,
                         const std::string& title);

}  // namespace sextant
