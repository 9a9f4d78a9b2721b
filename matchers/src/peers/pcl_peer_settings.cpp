// Settings of the PCL peer matchers (no PCL include: this file compiles fast).
#include <cmath>

#include "sextant/matchers/pcl_peers.hpp"

namespace sextant {

namespace {

bool positive(double v) {
  return v > 0.0 && std::isfinite(v);
}

bool fail(std::string* why, const char* problem) {
  if (why) *why = problem;
  return false;
}

}  // namespace

bool PclNdtSettings::valid(std::string* why) const {
  if (!positive(resolution)) return fail(why, "resolution must be a positive number of metres");
  if (!positive(step_size)) return fail(why, "step_size must be positive");
  if (!positive(epsilon)) return fail(why, "epsilon must be positive");
  if (max_iterations < 1) return fail(why, "max_iterations must be at least 1");
  if (!(outlier_ratio > 0.0 && outlier_ratio < 1.0)) return fail(why, "outlier_ratio must be in (0, 1)");
  return true;
}

bool PclIcpSettings::valid(std::string* why) const {
  if (!positive(max_correspondence_distance))
    return fail(why, "max_correspondence_distance must be positive");
  if (max_iterations < 1) return fail(why, "max_iterations must be at least 1");
  if (!(epsilon >= 0.0)) return fail(why, "epsilon must not be negative");
  if (!(fitness_epsilon >= 0.0)) return fail(why, "fitness_epsilon must not be negative");
  return true;
}

bool PclGicpSettings::valid(std::string* why) const {
  if (!positive(max_correspondence_distance))
    return fail(why, "max_correspondence_distance must be positive");
  if (max_iterations < 1) return fail(why, "max_iterations must be at least 1");
  if (!(epsilon >= 0.0)) return fail(why, "epsilon must not be negative");
  if (correspondence_randomness < 3) return fail(why, "correspondence_randomness must be at least 3");
  if (max_optimizer_iterations < 1) return fail(why, "max_optimizer_iterations must be at least 1");
  return true;
}

}  // namespace sextant
