#pragma once
// Whether a trajectory is one a car can drive (issue 22). A car does not slip sideways: over one
// step it follows (nearly) an arc, and an arc's chord leaves the start heading at half the heading
// change. The sensor is fixed to the car, so the car's heading in the sensor frame (its mounting)
// is one angle for the whole trajectory, estimated here from the steps themselves. A step's sideways
// slip is then its chord's component across the start heading turned by half the heading change:
// zero for any arc, whatever the turn and the mounting. A reference step that slips far more than a
// car can is no reference for that step (docs/matcher_defaults.md, "Where the reference cannot
// judge").
//
//   const VehicleSlip slip = vehicle_slip(reference_poses);
//   for (std::size_t k : slip.slipping(0.5)) ...  // step k → k + 1 is not a car's
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

namespace sextant {

struct VehicleSlip {
  /// The car's axis of travel in the sensor frame, as a yaw from the sensor's x axis in (−π/2, π/2]
  /// (forward and reverse share it) [rad]; NaN when no step moves `min_chord` or more.
  double mounting = 0.0;
  /// Per step k (pose k to k + 1): the sideways slip, signed (left of the axis positive); NaN for
  /// every step when the mounting is unknown [m].
  std::vector<double> slip;
  /// The steps whose slip exceeds `limit` in magnitude, in order.
  std::vector<std::size_t> slipping(double limit) const;
};

/// The slip of each step of `poses` (world ← sensor, in order; z up, so a step's heading change is
/// its yaw). The mounting is the median axis of the steps of at least `min_chord` metres horizontally
/// (shorter chords point nowhere in particular), taken about their chord-weighted axial mean.
VehicleSlip vehicle_slip(const std::vector<Eigen::Isometry3d>& poses, double min_chord = 0.5);

}  // namespace sextant
