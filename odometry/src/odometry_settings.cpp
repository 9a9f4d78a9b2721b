// Names of the guess and map modes, and the settings' checks.
#include <cmath>

#include "sextant/core/error.hpp"
#include "sextant/odometry/odometry.hpp"

namespace sextant {

std::string OdometrySettings::problem() const {
  if (!registration.matcher.make) return "no matcher named";
  if (!registration.sampler) return "no sampler named";
  if (map == OdometryMap::local_map && local_map_scans < 1) return "local_map_scans must be ≥ 1";
  if (map == OdometryMap::local_map && !(local_map_voxel > 0.0 && std::isfinite(local_map_voxel)))
    return "local_map_voxel must be a positive number of metres";
  if (!(min_range >= 0.0 && std::isfinite(min_range))) return "min_range must be ≥ 0 metres";
  if (!(max_acceleration >= 0.0 && std::isfinite(max_acceleration)))
    return "max_acceleration must be ≥ 0 m/s² (0: no check)";
  if (initial_pose && !initial_pose->matrix().allFinite()) return "the initial pose is not finite";
  for (const auto& T : odometry)
    if (!T.matrix().allFinite()) return "an odometry pose is not finite";
  return {};
}

OdometryGuess parse_odometry_guess(const std::string& text, const std::string& what) {
  if (text == "odometry") return OdometryGuess::odometry;
  if (text == "constant_velocity") return OdometryGuess::constant_velocity;
  if (text == "identity") return OdometryGuess::identity;
  throw InputError(what, "",
                   "unknown guess mode '" + text + "' (known: odometry, constant_velocity, identity)");
}

std::string to_string(OdometryGuess guess) {
  switch (guess) {
    case OdometryGuess::odometry: return "odometry";
    case OdometryGuess::constant_velocity: return "constant_velocity";
    case OdometryGuess::identity: return "identity";
  }
  return "?";
}

OdometryMap parse_odometry_map(const std::string& text, const std::string& what) {
  if (text == "scan") return OdometryMap::scan;
  if (text == "local_map") return OdometryMap::local_map;
  throw InputError(what, "", "unknown map mode '" + text + "' (known: scan, local_map)");
}

std::string to_string(OdometryMap map) {
  switch (map) {
    case OdometryMap::scan: return "scan";
    case OdometryMap::local_map: return "local_map";
  }
  return "?";
}

}  // namespace sextant
