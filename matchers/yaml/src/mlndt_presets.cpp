// The ML-NDT presets (matchers/yaml.hpp).
#include "sextant/matchers/yaml.hpp"

#include <algorithm>

#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/matchers/matcher_traits.hpp"

namespace sextant {
namespace {

struct Preset {
  const char* name;
  const char* settings;
};

// docs/matcher_defaults.md has the table these come from. `threads: 0`: a registration uses every
// thread TBB allows (`--jobs`); its result is the same for any thread count (mlndt_matcher.hpp).
constexpr Preset kPresets[] = {
    {"default",
     "{solver: lm, layers: 4, start_layer: 2, max_distance: 16, unmatched_penalty: 16, threads: 0}"},
    // Every key the library's defaults set differently, so that `thesis` stays the thesis (with the
    // unmatched charge of 50 it has always used: the thesis leaves that open).
    {"thesis",
     "{solver: newton, step_control: none, division: 8, layers: 4, start_layer: 2, "
     "iterations_per_layer: 3, max_iterations: 50, epsilon: 1.0e-4, function_tolerance: 0, "
     "unmatched_penalty: 50, "
     "max_distance: .inf, truncated_layers: 1, bounds_quantile: 0, min_relative_spread: 0, refine_first: "
     "false, precision_min_cell: 0}"},
    // Measured with the bounding box (before robust_bounds): its 6 layers over the robust box are too
    // fine for a GBS sample of a 64-beam scan (overlap 0.29 on the Velodyne pair).
    {"outdoor",
     "{solver: lm, layers: 6, start_layer: 2, max_distance: 16, unmatched_penalty: 16, bounds_quantile: 0, "
     "min_relative_spread: 0, threads: 0}"},
};

std::string known_names() {
  std::string known;
  for (const Preset& p : kPresets) known += (known.empty() ? "" : ", ") + std::string(p.name);
  return known;
}

}  // namespace

std::vector<std::string> mlndt_preset_names() {
  std::vector<std::string> names;
  for (const Preset& p : kPresets) names.emplace_back(p.name);
  return names;
}

YAML::Node mlndt_preset(const std::string& name, const std::string& file) {
  for (const Preset& p : kPresets)
    if (name == p.name) return YAML::Load(p.settings);
  throw InputError(file, "", "key 'preset': unknown preset '" + name + "' (known: " + known_names() + ")");
}

std::optional<YAML::Node> with_wide_basin(const std::string& matcher, const YAML::Node& settings) {
  if (!matcher_traits(matcher).has_wide_basin) return std::nullopt;
  YAML::Node wide = settings.IsMap() ? YAML::Clone(settings) : YAML::Node(YAML::NodeType::Map);
  if (!wide["wide_basin"].IsDefined()) wide["wide_basin"] = YAML::Node(YAML::NodeType::Map);
  return wide;
}

YAML::Node expand_mlndt_preset(const YAML::Node& settings, const std::string& file) {
  if (!settings.IsDefined() || !settings.IsMap() || !settings["preset"].IsDefined()) return settings;
  const YAML::Node preset_node = settings["preset"];
  if (!preset_node.IsScalar())
    throw InputError(file, at_line(yaml_line(preset_node)), "key 'preset': expected a preset name");
  const auto known = mlndt_preset_names();
  if (std::find(known.begin(), known.end(), preset_node.Scalar()) == known.end())
    throw InputError(
        file, at_line(yaml_line(preset_node)),
        "key 'preset': unknown preset '" + preset_node.Scalar() + "' (known: " + known_names() + ")");
  YAML::Node expanded = mlndt_preset(preset_node.Scalar(), file);
  // Deep copies: assigning a node would merge the caller's node memory into `expanded`'s, which
  // writes to `settings` (a data race when threads expand the same map, as parallel odometry does).
  for (const auto& entry : settings)
    if (entry.first.as<std::string>() != "preset")
      expanded[entry.first.as<std::string>()] = YAML::Clone(entry.second);
  return expanded;
}

}  // namespace sextant
