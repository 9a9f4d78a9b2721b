#include "sextant/synth/gnss.hpp"
#include "sextant/core/units.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <GeographicLib/LocalCartesian.hpp>

namespace sextant::synth {
std::vector<GnssRecord> simulate_gnss(const std::vector<Eigen::Isometry3d>& ground_truth,
                                      const std::vector<double>& stamps, const GnssSettings& s, Rng& rng) {
  const GeographicLib::LocalCartesian enu(s.origin_latitude, s.origin_longitude, s.origin_altitude);
  std::vector<GnssRecord> out;
  for (std::size_t i = 0; i < ground_truth.size(); ++i) {
    const Eigen::Isometry3d& T = ground_truth[i];
    GnssRecord r;
    r.stamp = i < stamps.size() ? stamps[i] : static_cast<double>(i);
    // Drawn last argument first: the order GCC gave these once-unsequenced draws (same data as before).
    const double up = rng.normal(0.0, s.sigma_vertical);
    const double north = rng.normal(0.0, s.sigma_horizontal);
    const double east = rng.normal(0.0, s.sigma_horizontal);
    const Eigen::Vector3d p = T.translation() + Eigen::Vector3d(east, north, up);
    enu.Reverse(p.x(), p.y(), p.z(), r.latitude, r.longitude, r.altitude);
    const Eigen::Matrix3d& R = T.linear();  // ZYX angles
    r.yaw = std::atan2(R(1, 0), R(0, 0)) + rng.normal(0.0, s.sigma_attitude_deg * kRadPerDeg);
    r.pitch = -std::asin(std::clamp(R(2, 0), -1.0, 1.0)) + rng.normal(0.0, s.sigma_attitude_deg * kRadPerDeg);
    r.roll = std::atan2(R(2, 1), R(2, 2)) + rng.normal(0.0, s.sigma_attitude_deg * kRadPerDeg);
    r.position_accuracy = s.sigma_horizontal;
    out.push_back(r);
  }
  return out;
}

std::string oxts_line(const GnssRecord& r) {
  // lat lon alt roll pitch yaw vn ve vf vl vu ax ay az af al au wx wy wz wf wl wu
  // pos_accuracy vel_accuracy navstat numsats posmode velmode orimode
  return fmt::format(
      "{:.12f} {:.12f} {:.6f} {:.9f} {:.9f} {:.9f} 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 {:.4f} 0.01 4 10 4 4 4",
      r.latitude, r.longitude, r.altitude, r.roll, r.pitch, r.yaw, r.position_accuracy);
}

}  // namespace sextant::synth
