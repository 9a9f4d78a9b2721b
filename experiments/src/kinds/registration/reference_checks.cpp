// The checks of each registration layout's `reference:` block (InputError with file, line, key),
// named in the layout table (registration/layouts/layouts.cpp).
#include <array>
#include <optional>

#include "registration/layouts/convergence_basin.hpp"
#include "registration/report.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"

namespace sextant {
namespace {

std::array<std::optional<double>, 6> read_six(const YAML::Node& node, const std::string& file,
                                              const std::string& key) {
  std::array<std::optional<double>, 6> out;
  const YAML::Node v = node[key];
  if (!v.IsDefined() || v.IsNull()) return out;
  if (!v.IsSequence() || v.size() != 6)
    throw InputError(file, at_line(yaml_line(v)),
                     "key '" + key + "': expected 6 values (tx, ty, tz, α, β, γ; null = not given)");
  for (std::size_t k = 0; k < 6; ++k) {
    const YAML::Node e = v[k];
    if (e.IsNull()) continue;
    try {
      out[k] = e.as<double>();
    } catch (const YAML::Exception&) {
      throw InputError(file, at_line(yaml_line(e)),
                       "key '" + key + "': '" + YAML::Dump(e) + "' is not a number or null");
    }
  }
  return out;
}

void check_accuracy_method(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  std::string table;
  double x = 0;
  in.read("table", table);
  for (const char* key : {"mean", "std", "max"}) (void)in.child(key);
  for (const char* key : {"success_percent", "seconds", "seconds_std", "iterations"}) in.read(key, x);
  in.finish();
  (void)read_parameter_reference(node, file);
}

void check_map_of(const YAML::Node& node, const std::string& file, const std::string& key,
                  void (*check)(const YAML::Node&, const std::string&)) {
  if (!node.IsDefined() || node.IsNull()) return;
  if (!node.IsMap()) throw InputError(file, at_line(yaml_line(node)), "key '" + key + "' must be a map");
  for (const auto& entry : node) check(entry.second, file);
}

void check_layer_row(const YAML::Node& node, const std::string& file) {
  if (!node.IsMap())
    throw InputError(file, at_line(yaml_line(node)),
                     "key 'table_5_8': each f maps start layer → [fail %, time s, error cm]");
  for (const auto& entry : node) {
    try {
      (void)entry.first.as<int>();
      const auto v = entry.second.as<std::vector<double>>();
      if (v.size() != 3) throw YAML::Exception(YAML::Mark::null_mark(), "size");
    } catch (const YAML::Exception&) {
      throw InputError(file, at_line(yaml_line(entry.second)),
                       "key 'table_5_8': expected start layer: [fail %, time s, error cm]");
    }
  }
}

void check_guideline(const YAML::Node& node, const std::string& file) {
  try {
    (void)node.as<std::vector<int>>();
  } catch (const YAML::Exception&) {
    throw InputError(file, at_line(yaml_line(node)),
                     "key 'guideline': each f maps to the list of best start layers");
  }
}

/// table_5_7: sampling → {ndt: method name, mlndt: method name}.
void check_sampling_row(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  std::string name;
  in.read("ndt", name);
  in.read("mlndt", name);
  in.finish();
}

/// table_5_9: sampler → [iterations, matched %, time s, success %].
void check_strategy_row(const YAML::Node& node, const std::string& file) {
  try {
    if (node.as<std::vector<double>>().size() == 4) return;
  } catch (const YAML::Exception&) {
  }
  throw InputError(file, at_line(yaml_line(node)),
                   "key 'table_5_9': expected sampler: [iterations, matched %, time s, success %]");
}

}  // namespace

ParameterReference read_parameter_reference(const YAML::Node& node, const std::string& file) {
  ParameterReference r;
  if (!node.IsMap()) return r;
  r.mean = read_six(node, file, "mean");
  r.std = read_six(node, file, "std");
  r.max = read_six(node, file, "max");
  return r;
}

void check_accuracy_reference(const ExperimentConfig& config) {
  SettingsReader in(config.reference, config.file);
  const YAML::Node odometry = in.child("odometry");
  if (odometry.IsDefined() && !odometry.IsNull()) check_accuracy_method(odometry, config.file);
  check_map_of(in.child("methods"), config.file, "methods", check_accuracy_method);
  in.finish();
}

void check_basin_reference(const ExperimentConfig& config) {
  (void)read_basin_report_settings(config);
}

void check_init_layer_reference(const ExperimentConfig& config) {
  SettingsReader in(config.reference, config.file);
  check_map_of(in.child("table_5_8"), config.file, "table_5_8", check_layer_row);
  check_map_of(in.child("guideline"), config.file, "guideline", check_guideline);
  in.finish();
}

void check_sampling_reference(const ExperimentConfig& config) {
  SettingsReader in(config.reference, config.file);
  check_map_of(in.child("methods"), config.file, "methods", check_accuracy_method);
  check_map_of(in.child("table_5_7"), config.file, "table_5_7", check_sampling_row);
  in.finish();
}

void check_strategies_reference(const ExperimentConfig& config) {
  SettingsReader in(config.reference, config.file);
  check_map_of(in.child("table_5_9"), config.file, "table_5_9", check_strategy_row);
  SettingsReader sampling(in.child("sampling_seconds"), config.file);
  SettingsReader below(in.child("mean_error_below"), config.file);
  double x = 0;
  for (const char* key : {"fbs", "gbs"}) sampling.read(key, x);
  for (const char* key : {"translation_cm", "rotation_deg"}) below.read(key, x);
  sampling.finish();
  below.finish();
  in.finish();
}

void check_zero_guess_reference(const ExperimentConfig& config) {
  SettingsReader in(config.reference, config.file);
  double x = 0;
  for (const char* key : {"iterations", "error_cm"}) in.read(key, x);
  in.finish();
}

}  // namespace sextant
