#pragma once
// The campus settings from YAML (target Sextant::synth_yaml; the library takes CampusSettings).
#include <cstdint>
#include <string>

#include <yaml-cpp/yaml.h>

#include "sextant/synth/settings.hpp"

namespace sextant::synth {

/// Maps YAML (sections world, trajectory, sensor, odometry, gnss) onto the defaults. Unknown
/// keys, wrong types and invalid values throw InputError naming file, line and key. When
/// `seed` is given, an optional top-level `seed` key is read into it (campus.yaml has one).
CampusSettings read_campus_settings(const YAML::Node& node, const std::string& file,
                                    std::uint64_t* seed = nullptr);

}  // namespace sextant::synth
