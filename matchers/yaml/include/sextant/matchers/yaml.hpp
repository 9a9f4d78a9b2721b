#pragma once
// The matcher and sampler specs from YAML (target Sextant::matchers_yaml; the library takes the specs,
// matcher_spec.hpp). A YAML file chooses `matcher: mlndt` by name; each reader maps a settings map
// onto the struct's defaults, and every problem (an unknown name or key, a wrong type, an invalid
// value) is an InputError naming the file, the line and the key. Read once, at the edge:
//
//   MatcherSpec spec = read_matcher_spec("mlndt", settings_node, "exp.yaml");
//   MatcherChoice choice = matcher_choice(spec);  // for register_pair and odometry
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

#include "sextant/matchers/fbmlndt_matcher.hpp"
#include "sextant/matchers/icp.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/matcher_spec.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/mlndt_presets.hpp"
#include "sextant/matchers/ndt_matcher.hpp"
#include "sextant/matchers/pcl_peers.hpp"
#include "sextant/matchers/sampler.hpp"
#include "sextant/matchers/samplers.hpp"
#include "sextant/matchers/wide_basin_settings.hpp"

namespace sextant {

// --- Settings readers (null node: the defaults) ---

/// Keys: division, layers, start_layer, solver (newton | lm | ceres), iterations_per_layer,
/// max_iterations, unmatched_penalty, max_distance, truncated_layers, epsilon, step_control, the
/// cell statistics (min_points, max_eigen_ratio, min_spread, min_relative_spread), bounds_quantile,
/// refine_first, dof, threads, precision_min_cell, precision_min_coverage, precision_max_eigen_ratio,
/// precision_spacing_cells,
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

// --- The specs by name ---

/// The matcher (sampler) named `name` (matcher_names(), sampler_names()) with `settings` (null: its
/// defaults), read and checked.
MatcherSpec read_matcher_spec(const std::string& name, const YAML::Node& settings, const std::string& file);
SamplerSpec read_sampler_spec(const std::string& name, const YAML::Node& settings, const std::string& file);

/// read_matcher_spec (read_sampler_spec) and the bare matcher (sampler) it specifies.
std::unique_ptr<Matcher> make_matcher(const std::string& name, const YAML::Node& settings = YAML::Node(),
                                      const std::string& file = "<settings>");
std::unique_ptr<Sampler> make_sampler(const std::string& name, const YAML::Node& settings = YAML::Node(),
                                      const std::string& file = "<settings>");

}  // namespace sextant
