#pragma once
// What two scans can both see (issue 22). A lidar sees a band of elevations out to a range, both
// fixed to the sensor, so every scan's coverage ends where its own sensor's view ends: at the top and
// the bottom of a wall, on the ground around the vehicle, at the farthest returns. Registered whole,
// two scans' coverage edges coincide only at no motion, and the cells those edges cross pull every
// step short. Registering only what both sensors see — the reference's points that the input's
// sensor sees from the guessed pose, the input's points that the reference's sensor sees — puts the
// same edges in both: ML-NDT's default in `sextant odometry`, measured more accurate on the benchmark
// sequences (`--whole-scans` turns it off: docs/matcher_defaults.md, "Registering only what both scans
// can see").
#include <utility>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/core/units.hpp"
#include "sextant/matchers/sensor_kind.hpp"

namespace sextant {

/// A sensor's view, from its own points: the band of elevations (as slopes z / √(x² + y²), the
/// tangents of the lowest and highest elevation; ∓∞ where the band reaches straight down or up), the
/// sector of azimuths (a solid-state lidar's field of view; the whole circle for a spinning one) and
/// the farthest range.
struct SensorView {
  double min_slope = -1.0, max_slope = 1.0;  ///< tan of the lowest and highest elevation seen
  double max_range = 0.0;                    ///< [m]
  /// The sector of azimuths about the sensor's vertical: the directions within `azimuth_half_width` of
  /// `azimuth_centre`; the whole circle when the half width is π or more [rad]
  double azimuth_centre = 0.0, azimuth_half_width = kPi;
  /// Whether a point in the sensor's frame lies in the view (false for a non-finite point).
  bool sees(const Eigen::Vector3d& p) const;
};

/// The view of a scan in its own sensor frame: the extremes of its points' elevations, widened by 1°
/// on each side, and of their ranges (points straight above or below the sensor are left out of the
/// band). A spinning lidar sees the whole circle of azimuths; a solid-state one (`sensor`,
/// sensor_kind.hpp) its field of view: the circle less the largest gap between the scan's azimuths,
/// widened by 1° on each side, when that gap is more than half the circle (the whole circle otherwise).
/// A scan without a point off the vertical sees nothing.
SensorView sensor_view(const PointCloud& scan, SensorKind sensor = SensorKind::spinning);

/// The points of `reference` (in the frame of the sensor with `reference_view`) that the input's
/// sensor sees from `guess` (reference ← input), and those of `input` (in its sensor's frame) that
/// the reference's sensor sees. `reference` may be a local map of several scans in that frame.
std::pair<PointCloud, PointCloud> common_view(const PointCloud& reference, const SensorView& reference_view,
                                              const PointCloud& input, const SensorView& input_view,
                                              const Eigen::Isometry3d& guess);

}  // namespace sextant
