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
  if (!(min_range >= 0.0 && std::isfinite(min_range))) return "min_range must be a finite number ≥ 0 metres";
  if (!(max_acceleration >= 0.0 && std::isfinite(max_acceleration)))
    return "max_acceleration must be a finite number ≥ 0 m/s² (0: no check)";
  if (initial_pose && !initial_pose->matrix().allFinite()) return "the initial pose is not finite";
  for (const auto& T : odometry)
    if (!T.matrix().allFinite()) return "an odometry pose is not finite";
  return {};
}

bool from_string(const std::string& text, OdometryGuess* out) {
  return from_name(kOdometryGuessNames, text, out);
}

std::string to_string(OdometryGuess guess) {
  return name_of(kOdometryGuessNames, guess);
}

bool from_string(const std::string& text, OdometryMap* out) {
  return from_name(kOdometryMapNames, text, out);
}

std::string to_string(OdometryMap map) {
  return name_of(kOdometryMapNames, map);
}

}  // namespace sextant
