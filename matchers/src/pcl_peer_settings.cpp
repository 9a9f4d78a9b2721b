// Settings of the PCL peer matchers (no PCL include: this file compiles fast).
#include <cmath>

#include "sextant/core/settings_reader.hpp"
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

template <class Settings>
void check(const Settings& s, const SettingsReader& in) {
  in.finish();
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
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

PclNdtSettings read_pcl_ndt_settings(const YAML::Node& node, const std::string& file) {
  PclNdtSettings s;
  SettingsReader in(node, file);
  in.read("resolution", s.resolution);
  in.read("step_size", s.step_size);
  in.read("epsilon", s.epsilon);
  in.read("max_iterations", s.max_iterations);
  in.read("outlier_ratio", s.outlier_ratio);
  check(s, in);
  return s;
}

PclIcpSettings read_pcl_icp_settings(const YAML::Node& node, const std::string& file) {
  PclIcpSettings s;
  SettingsReader in(node, file);
  in.read("max_correspondence_distance", s.max_correspondence_distance);
  in.read("max_iterations", s.max_iterations);
  in.read("epsilon", s.epsilon);
  in.read("fitness_epsilon", s.fitness_epsilon);
  check(s, in);
  return s;
}

PclGicpSettings read_pcl_gicp_settings(const YAML::Node& node, const std::string& file) {
  PclGicpSettings s;
  SettingsReader in(node, file);
  in.read("max_correspondence_distance", s.max_correspondence_distance);
  in.read("max_iterations", s.max_iterations);
  in.read("epsilon", s.epsilon);
  in.read("correspondence_randomness", s.correspondence_randomness);
  in.read("max_optimizer_iterations", s.max_optimizer_iterations);
  check(s, in);
  return s;
}

std::unique_ptr<Matcher> make_pcl_ndt_matcher(const YAML::Node& settings, const std::string& file) {
  return make_pcl_ndt(read_pcl_ndt_settings(settings, file));
}
std::unique_ptr<Matcher> make_pcl_icp_matcher(const YAML::Node& settings, const std::string& file) {
  return make_pcl_icp(read_pcl_icp_settings(settings, file));
}
std::unique_ptr<Matcher> make_pcl_gicp_matcher(const YAML::Node& settings, const std::string& file) {
  return make_pcl_gicp(read_pcl_gicp_settings(settings, file));
}

}  // namespace sextant
