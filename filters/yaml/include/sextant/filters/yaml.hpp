#pragma once
// The filter specs by name from YAML, and the plane-SLAM settings (target Sextant::filters_yaml; the
// library takes the specs, filter_spec.hpp). Every problem (an unknown name or key, a wrong type, an
// invalid value) is an InputError naming the file, the line and the key. Read once, at the edge:
//
//   FilterSpec spec = read_filter_spec("ukf", settings_node, "exp.yaml");
//   auto filter = make_filter(spec, model);
//   PlaneSlamSettings s = read_plane_slam_settings(node, "e12.yaml");
#include <memory>
#include <string>

#include <yaml-cpp/yaml.h>

#include "sextant/filters/filter.hpp"
#include "sextant/filters/filter_spec.hpp"
#include "sextant/filters/plane_slam.hpp"

namespace sextant {

/// The filter `name` (filter_names()) with `settings` (null: its defaults), read and checked; `pose_dim`
/// > 0 checks what depends on the model (an ESEIF relocation prior: one σ per pose entry).
FilterSpec read_filter_spec(const std::string& name, const YAML::Node& settings, const std::string& file,
                            int pose_dim = 0);

/// read_filter_spec (checked against `model`) and the filter it specifies.
std::unique_ptr<Filter> make_filter(const std::string& name, std::shared_ptr<const SlamModel> model,
                                    const YAML::Node& settings = YAML::Node(),
                                    const std::string& file = "<settings>");

/// Keys: filter, filter_settings (map, the filter's keys: read_filter_spec), extraction (map,
/// read_plane_extraction_settings), association (map, read_association_settings) and the scalar
/// field names of PlaneSlamSettings. filter_factory builds the filter of `filter` and `filter_settings`.
PlaneSlamSettings read_plane_slam_settings(const YAML::Node& node, const std::string& file);

}  // namespace sextant
