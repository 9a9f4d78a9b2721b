#include "kit/adaptive_start.hpp"

#include <cmath>

#include "sextant/core/settings_reader.hpp"

namespace sextant {

AdaptiveStartSettings read_adaptive_start(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  AdaptiveStartSettings s;
  in.read("max_translation", s.max_translation);
  in.read("max_rotation_deg", s.max_rotation_deg);
  in.read("middle_rate", s.middle_rate);
  in.read("first_rate", s.first_rate);
  in.read("middle_layer", s.middle_layer);
  in.read("first_layer", s.first_layer);
  in.finish();
  if (!(s.max_translation > 0) || !(s.max_rotation_deg > 0))
    in.fail("", "adaptive_start: max_translation and max_rotation_deg must be positive");
  if (!(s.middle_rate >= 0 && s.middle_rate <= s.first_rate && s.first_rate <= 1))
    in.fail("", "adaptive_start: need 0 ≤ middle_rate ≤ first_rate ≤ 1");
  if (s.first_layer < 1 || s.middle_layer < s.first_layer)
    in.fail("", "adaptive_start: need 1 ≤ first_layer ≤ middle_layer");
  return s;
}

int adaptive_start_layer(const AdaptiveStartSettings& s, int last_layer, std::size_t failures,
                         std::size_t registrations) {
  if (registrations == 0) return last_layer;
  const double rate = static_cast<double>(failures) / static_cast<double>(registrations);
  if (rate > s.first_rate) return s.first_layer;
  if (rate > s.middle_rate) return s.middle_layer;
  return last_layer;
}

bool adaptive_failure(const AdaptiveStartSettings& s, const Eigen::Isometry3d& estimate,
                      const Eigen::Isometry3d& odometry) {
  const Eigen::Isometry3d d = odometry.inverse() * estimate;
  const double angle = Eigen::AngleAxisd(d.rotation()).angle() * 180.0 / 3.14159265358979323846;
  // NaN compares false: a non-finite estimate counts as a failure.
  return !(d.translation().norm() <= s.max_translation && angle <= s.max_rotation_deg);
}

}  // namespace sextant
