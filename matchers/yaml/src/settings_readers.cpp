// The matcher settings from YAML (Sextant::matchers_yaml): ML-NDT, NDT, ICP and their shared parts
// (optimiser, cell statistics, DOF mask, precision stage, wide basin), and the GBS sampler.
#include "readers.hpp"

#include "sextant/matchers/yaml.hpp"

namespace sextant {

void read_optimizer_settings(SettingsReader& in, const std::string& known_solvers, OptimizerSettings& s) {
  std::string solver = to_string(s.solver), control = to_string(s.step_control);  // the defaults
  if (in.read("solver", solver) && !from_string(solver, &s.solver))
    in.fail("solver", "unknown solver '" + solver + "' (known: " + known_solvers + ")");
  in.read("max_iterations", s.max_iterations);
  in.read("epsilon", s.epsilon);
  in.read("function_tolerance", s.function_tolerance);
  bool line_search = false;
  const bool legacy = in.read_alias("line_search", line_search);
  if (legacy) s.step_control = line_search ? StepControl::kLineSearch : StepControl::kNone;
  if (in.read("step_control", control)) {
    if (legacy) in.fail("step_control", "give step_control or line_search, not both");
    if (!from_string(control, &s.step_control))
      in.fail("step_control",
              "key 'step_control': '" + control +
                  "' is not none, line_search, more_thuente, trust_region or trust_region_last");
  }
  in.read("line_search_mu", s.line_search.mu);
  in.read("line_search_eta", s.line_search.eta);
  in.read("line_search_max_step", s.line_search.max_step);
  in.read("line_search_iterations", s.line_search.iterations);
  read_dof_mask(in, "dof", s.dof);
}

void read_cell_stats_settings(SettingsReader& in, CellStatsSettings& s) {
  in.read("min_points", s.min_points);
  in.read("max_eigen_ratio", s.max_eigen_ratio);
  in.read("min_spread", s.min_spread);
  in.read("min_relative_spread", s.min_relative_spread);
}

void read_dof_mask(SettingsReader& in, const std::string& key, DofMask& mask) {
  std::vector<std::string> names = mask.names();  // the default, recorded when the key is absent
  if (!in.read(key, names)) return;
  std::string why;
  if (!DofMask::from_names(names, mask, &why)) in.fail(key, why);
}

void read_precision_settings(SettingsReader& in, PrecisionSettings& s) {
  in.read("precision_min_cell", s.min_cell);
  in.read("precision_min_coverage", s.min_coverage);
  in.read("precision_max_eigen_ratio", s.max_eigen_ratio);
  in.read("precision_spacing_cells", s.spacing_cells);
}

WideBasinSettings read_wide_basin_settings(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  WideBasinSettings s;
  s.enabled = true;
  in.read("yaw_step_deg", s.yaw_step_deg);
  in.read("yaw_range_deg", s.yaw_range_deg);
  in.read("translation_step", s.translation_step);
  in.read("translation_range", s.translation_range);
  in.read("tilt_step_deg", s.tilt_step_deg);
  in.read("tilt_range_deg", s.tilt_range_deg);
  in.read("tilt_candidates", s.tilt_candidates);
  in.read("sample_points", s.sample_points);
  in.read("candidates", s.candidates);
  in.read("horizon_candidates", s.horizon_candidates);
  in.read("prescreen_points", s.prescreen_points);
  in.read("prescreen_keep", s.prescreen_keep);
  in.read("max_distance", s.max_distance);
  in.finish();
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
  return s;
}

MlndtSettings read_mlndt_settings(const YAML::Node& node, const std::string& file) {
  // A deep copy: yaml-cpp's lookups in a non-const node write to its memory, and parallel odometry steps
  // read one settings map at once. (YAML::Clone keeps no line numbers: an error in a map with a
  // preset names line 1, as the merged copy of the preset's map before it did.)
  SettingsReader in(node.IsMap() ? YAML::Clone(node) : node, file);
  // `preset:` first (mlndt_presets.hpp), the other keys override it; not recorded: the resolved
  // settings are the keys it set.
  MlndtSettings s;
  std::string preset;
  if (in.read_alias("preset", preset)) {
    const std::optional<MlndtSettings> named = mlndt_preset(preset);
    if (!named) {
      std::string known;
      for (const std::string& n : mlndt_preset_names()) known += (known.empty() ? "" : ", ") + n;
      in.fail("preset", "key 'preset': unknown preset '" + preset + "' (known: " + known + ")");
    }
    s = *named;
  }
  in.read("division", s.pyramid.division);
  in.read("layers", s.pyramid.layers);
  in.read("bounds_quantile", s.pyramid.bounds_quantile);
  in.read("start_layer", s.start_layer);
  in.read("refine_first", s.refine_first);
  read_precision_settings(in, s.precision);
  in.read("unmatched_penalty", s.unmatched_penalty);
  in.read("max_distance", s.max_distance);
  in.read("truncated_layers", s.truncated_layers);
  if (in.read("threads", s.threads) && s.threads < 0)
    in.fail("threads", "threads must be ≥ 0 (0: all hardware threads)");
  read_cell_stats_settings(in, s.pyramid.cells);
  read_optimizer_settings(in, "newton lm ceres", s.optimizer);
  in.read("iterations_per_layer", s.optimizer.iterations_per_stage);
  if (in.has("wide_basin")) s.wide_basin = read_wide_basin_settings(in.child("wide_basin"), file);
  in.finish();
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
  return s;
}

NdtSettings read_ndt_settings(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  NdtSettings s;
  in.read("cell_size", s.cell_size);
  in.read("volume_divisions", s.volume_divisions);
  in.read("outlier_ratio", s.outlier_ratio);
  in.read("trilinear", s.trilinear);
  if (in.read("threads", s.threads) && s.threads < 0)
    in.fail("threads", "threads must be ≥ 0 (0: all hardware threads)");
  read_cell_stats_settings(in, s.cells);
  read_optimizer_settings(in, "newton lm", s.optimizer);
  in.finish();
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
  return s;
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

GridSamplerSettings read_grid_sampler_settings(const YAML::Node& settings, const std::string& file) {
  SettingsReader in(settings, file);
  GridSamplerSettings s;
  in.read("cell_size", s.cell_size);
  in.read("max_per_cell", s.max_per_cell);
  in.read("min_per_cell", s.min_per_cell);
  in.finish();
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
  return s;
}

}  // namespace sextant
