#include <cmath>

#include "sextant/core/units.hpp"
#include "sextant/matchers/icp.hpp"

namespace sextant {

bool IcpSettings::valid(std::string* why) const {
  const auto fail = [why](const char* problem) {
    if (why) *why = problem;
    return false;
  };
  if (!(max_correspondence_distance > 0.0 && max_correspondence_distance <= kMaxSettingLength))
    return fail("max_correspondence_distance must be a positive number of metres, at most 1000");
  if (max_iterations < 1) return fail("max_iterations must be at least 1");
  if (!(epsilon > 0.0) || !std::isfinite(epsilon)) return fail("epsilon must be positive");
  if (min_correspondences < 6) return fail("min_correspondences must be at least 6");
  if (normal_neighbours < 3) return fail("normal_neighbours must be at least 3");
  return dof.valid(why);
}

}  // namespace sextant
