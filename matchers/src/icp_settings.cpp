#include <cmath>

#include "sextant/core/settings_reader.hpp"
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

IcpSettings read_icp_settings(IcpObjective objective, const YAML::Node& node, const std::string& file) {
  IcpSettings s;
  SettingsReader in(node, file);
  in.read("max_correspondence_distance", s.max_correspondence_distance);
  in.read("max_iterations", s.max_iterations);
  in.read("epsilon", s.epsilon);
  in.read("min_correspondences", s.min_correspondences);
  if (objective == IcpObjective::kPointToPlane) in.read("normal_neighbours", s.normal_neighbours);
  read_dof_mask(in, "dof", s.dof);
  in.finish();
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
  return s;
}

std::unique_ptr<Matcher> make_icp_p2p_matcher(const YAML::Node& settings, const std::string& file) {
  return make_icp(IcpObjective::kPointToPoint,
                  read_icp_settings(IcpObjective::kPointToPoint, settings, file));
}

std::unique_ptr<Matcher> make_icp_p2l_matcher(const YAML::Node& settings, const std::string& file) {
  return make_icp(IcpObjective::kPointToPlane,
                  read_icp_settings(IcpObjective::kPointToPlane, settings, file));
}

}  // namespace sextant
