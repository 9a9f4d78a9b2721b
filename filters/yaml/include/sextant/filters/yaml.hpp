#pragma once
// The filters by name with YAML settings, and the plane-SLAM and room-simulation settings from YAML
// (target Sextant::filters_yaml; the library takes the plain structs and factories). Every problem
// (an unknown key, a wrong type, an invalid value) is an InputError naming the file, the line and
// the key.
//
//   auto filter = make_filter("ukf", model, settings_node, "exp.yaml");
//   PlaneSlamSettings s = read_plane_slam_settings(node, "e12.yaml");
#include <memory>
#include <string>

#include <yaml-cpp/yaml.h>

#include "sextant/core/registry.hpp"
#include "sextant/filters/filter.hpp"
#include "sextant/filters/plane_slam.hpp"

namespace sextant {

/// Factory signature: (model, settings node — may be null for defaults, file name for messages).
using FilterRegistry =
    Registry<Filter, std::shared_ptr<const SlamModel>, const YAML::Node&, const std::string&>;

/// All filters (ekf, ukf, ckf, rspkf, seif, eif, eseif), filled with the built-ins on first use.
FilterRegistry& filter_registry();

std::unique_ptr<Filter> make_filter(const std::string& name, std::shared_ptr<const SlamModel> model,
                                    const YAML::Node& settings = YAML::Node(),
                                    const std::string& file = "<settings>");

/// Keys: filter, filter_settings (map, the filter's keys: filter_registry), extraction (map,
/// read_plane_extraction_settings), association (map, read_association_settings) and the scalar
/// field names of PlaneSlamSettings. The filter's keys are checked now; filter_factory builds it
/// with them.
PlaneSlamSettings read_plane_slam_settings(const YAML::Node& node, const std::string& file);

}  // namespace sextant
