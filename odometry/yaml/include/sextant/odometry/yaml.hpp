#pragma once
// The odometry's matcher and sampler by registry name with YAML settings (target
// Sextant::odometry_yaml; the library takes factories, OdometryRegistration):
//
//   OdometrySettings s;
//   s.registration = odometry_registration({"mlndt", YAML::Load("{preset: outdoor}"), "gbs", {}});
#include <string>

#include <yaml-cpp/yaml.h>

#include "sextant/matchers/yaml.hpp"
#include "sextant/odometry/odometry.hpp"

namespace sextant {

/// The matcher and sampler of a registration, by registry name (matchers/yaml.hpp).
struct OdometryMethod {
  std::string matcher = "mlndt";
  YAML::Node settings;  ///< matcher settings (may say `preset:`, matchers/yaml.hpp); null = defaults
  std::string sampler = "gbs";
  YAML::Node sampler_settings;  ///< null = defaults
};

/// The factories run_odometry builds its matchers and samplers with: they read the settings at
/// every call, their errors name "<odometry matcher>" ("<odometry matcher, recovery>" for the wide
/// basin) and "<odometry sampler>". An empty name leaves its factory empty (the settings' problem()
/// then says "no matcher named" / "no sampler named").
OdometryRegistration odometry_registration(const OdometryMethod& method);

}  // namespace sextant
