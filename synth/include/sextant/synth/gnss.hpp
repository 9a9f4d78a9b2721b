#pragma once
// A GNSS/INS track like KITTI raw's OXTS records: the true sensor position converted to
// WGS84 around a geodetic origin (world x = east, y = north, z = up), with Gaussian noise.
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/rng.hpp"
#include "sextant/synth/settings.hpp"

namespace sextant::synth {

struct GnssRecord {
  double stamp = 0.0;                         ///< [s]
  double latitude = 0.0, longitude = 0.0;     ///< [deg]
  double altitude = 0.0;                      ///< [m] above the WGS84 ellipsoid
  double roll = 0.0, pitch = 0.0, yaw = 0.0;  ///< OXTS convention: R = Rz(yaw)·Ry(pitch)·Rx(roll) [rad]
  double position_accuracy = 0.0;             ///< [m]
};

std::vector<GnssRecord> simulate_gnss(const std::vector<Eigen::Isometry3d>& ground_truth,
                                      const std::vector<double>& stamps, const GnssSettings& settings,
                                      Rng& rng);

/// The 30 space-separated fields of a KITTI OXTS line (velocities and accelerations are 0:
/// the vehicle stands still while it scans).
std::string oxts_line(const GnssRecord& record);

}  // namespace sextant::synth
