#pragma once
// The matchers and samplers from YAML (target Sextant::matchers_yaml; the library takes the plain
// settings structs, matcher_choice.hpp). A YAML file chooses `method: mlndt` by registry name; each
// reader maps a settings map onto the struct's defaults, and every problem (an unknown key, a wrong
// type, an invalid value) is an InputError naming the file, the line and the key.
//
//   auto matcher = make_matcher("mlndt", settings_node, "exp.yaml");
//   MatcherChoice choice = matcher_choice("mlndt", settings_node, "exp.yaml");  // for register_pair
//
// ML-NDT presets (mlndt_presets.hpp): a map of `mlndt` (and `fbmlndt`, which forwards the mlndt keys)
// may say `preset: <name>`; it starts from that preset's settings and its other keys override them.
// One rule everywhere: `default` unless a preset is named (`sextant match`, `sextant odometry`, the
// Python module, the library); every experiment config of the thesis' nineteen says `preset: thesis`
// and overrides what it deliberately changes, which its report section names.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "sextant/core/registry.hpp"
#include "sextant/matchers/fbmlndt_matcher.hpp"
#include "sextant/matchers/icp.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/matcher_choice.hpp"
#include "sextant/matchers/mlndt_global_init.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/mlndt_presets.hpp"
#include "sextant/matchers/ndt_matcher.hpp"
#include "sextant/matchers/pcl_peers.hpp"
#include "sextant/matchers/sampler.hpp"
#include "sextant/matchers/samplers.hpp"

namespace sextant {

// --- Settings readers (null node: the defaults) ---

/// Keys: division, layers, start_layer, solver (newton | lm | ceres), iterations_per_layer,
/// max_iterations, unmatched_penalty, max_distance, truncated_layers, epsilon, step_control, the
/// cell statistics (min_points, max_eigen_ratio, min_spread, min_relative_spread), bounds_quantile,
/// refine_first, dof, threads, precision_min_cell, precision_min_coverage, precision_max_eigen_ratio,
/// wide_basin (a map) and `preset:` (expanded first, the other keys override it).
MlndtSettings read_mlndt_settings(const YAML::Node& node, const std::string& file);
/// The mlndt keys, plus seed, features (plane extraction), fallback (gbs | add_gbs | none),
/// constraints, fallback_gbs (GBS keys) and verify.
FbmlndtSettings read_fbmlndt_settings(const YAML::Node& node, const std::string& file);
/// Keys: cell_size, volume_divisions, outlier_ratio, trilinear, threads, the cell statistics and
/// the optimiser keys (solver newton | lm).
NdtSettings read_ndt_settings(const YAML::Node& node, const std::string& file);
/// Reads the `wide_basin` map (enabled = true); unknown keys are InputErrors.
WideBasinSettings read_wide_basin_settings(const YAML::Node& node, const std::string& file);
/// Reads the settings of `objective` (p2p rejects `normal_neighbours`).
IcpSettings read_icp_settings(IcpObjective objective, const YAML::Node& node, const std::string& file);
PclNdtSettings read_pcl_ndt_settings(const YAML::Node& node, const std::string& file);
PclIcpSettings read_pcl_icp_settings(const YAML::Node& node, const std::string& file);
PclGicpSettings read_pcl_gicp_settings(const YAML::Node& node, const std::string& file);
/// Keys cell_size, max_per_cell, min_per_cell.
GridSamplerSettings read_grid_sampler_settings(const YAML::Node& settings, const std::string& file);

// --- The registries: by name, with YAML settings ---

/// Factory signature: (settings node — may be null for defaults, file name for error messages).
using MatcherRegistry = Registry<Matcher, const YAML::Node&, const std::string&>;
using SamplerRegistry = Registry<Sampler, const YAML::Node&, const std::string&>;

/// All matchers (samplers), filled with the built-ins on first use.
MatcherRegistry& matcher_registry();
SamplerRegistry& sampler_registry();

std::unique_ptr<Matcher> make_matcher(const std::string& name, const YAML::Node& settings = YAML::Node(),
                                      const std::string& file = "<settings>");
std::unique_ptr<Sampler> make_sampler(const std::string& name, const YAML::Node& settings = YAML::Node(),
                                      const std::string& file = "<settings>");

/// The matcher `name` with `settings` for register_pair and odometry: make() and make_wide() read
/// the settings at every call (so a SettingsRecording records them), their errors name `file` (the
/// wide basin's: `wide_file`, empty = `file`); the wide basin as with_wide_basin() gives it.
MatcherChoice matcher_choice(const std::string& name, const YAML::Node& settings, const std::string& file,
                             const std::string& wide_file = "");
/// The sampler `name` with `settings`, read at every call; errors name `file`.
SamplerFactory sampler_factory(const std::string& name, const YAML::Node& settings, const std::string& file);

// --- The wide basin ---

/// `settings` (mlndt or fbmlndt) with the wide basin switched on (`wide_basin: {}` unless it has its
/// own); nothing for a matcher without a wide basin.
std::optional<YAML::Node> with_wide_basin(const std::string& matcher, const YAML::Node& settings);

}  // namespace sextant
