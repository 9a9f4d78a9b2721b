#pragma once
// What run_odometry reads of a sequence beside its scans (private to Sextant::odometry): the scans'
// times (the constant-velocity guess' scale, how far a step can reach, how long a sweep takes), the
// odometry poses the odometry guess needs, and the pose the chain starts at.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/dataset.hpp"
#include "sextant/odometry/deskew.hpp"
#include "sextant/odometry/odometry.hpp"

namespace sextant::odometry_detail {

/// The dataset's path, else its name, for messages.
std::string dataset_label(const Dataset& dataset);

/// Δt_i / Δt_{i−1} around scan i (the constant-velocity guess's scale), 1 without usable times.
double time_ratio(const Dataset& dataset, std::size_t i);

/// How far from the constant-velocity guess scan i can lie (reachable_departure); ∞ without times.
double step_reach(const Dataset& dataset, std::size_t i, double max_acceleration);

/// The sweep of `scan` at the velocity of `motion`, the motion from scan `from` to scan `to` of the
/// dataset: made in the time between their stamps, or without stamps in the scan's own sweep (sweep_span:
/// scans back to back, as a lidar streams them). Unknown (the scan is kept as read) for a
/// scan without times or a motion that is exactly none.
SweepMotion sweep_between(const Dataset& dataset, std::size_t from, std::size_t to, const PointCloud& scan,
                          const Eigen::Isometry3d& motion);

/// The odometry poses the guess mode needs (empty unless guess = odometry); InputError naming the
/// dataset when a scan has none.
std::vector<Eigen::Isometry3d> odometry_poses(const Dataset& dataset, const OdometrySettings& s,
                                              std::size_t first, std::size_t count);

/// The settings' initial pose, else the scan's ground truth, else its odometry, else the identity.
Eigen::Isometry3d start_pose(const Dataset& dataset, const OdometrySettings& s, std::size_t first);

}  // namespace sextant::odometry_detail
