// Helpers shared by the registration report layouts, and the reference-block checks.
#include "registration/report.hpp"

#include "registration/layouts/convergence_basin.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/core/units.hpp"

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

std::vector<double> isometry_to_series(const Eigen::Isometry3d& T) {
  std::vector<double> s;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) s.push_back(T.matrix()(r, c));
  }
  return s;
}

Eigen::Isometry3d series_to_isometry(const std::vector<double>& s) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c)
      T.matrix()(r, c) = s.size() == 12 ? s[static_cast<std::size_t>(4 * r + c)] : kNaN;
  }
  return T;
}

RegistrationSample sample_of(const RunRow& row) {
  RegistrationSample s;
  const auto series = [&](const char* name) {
    const auto it = row.series.find(name);
    return it == row.series.end() ? std::vector<double>{} : it->second;
  };
  s.estimate = series_to_isometry(series("estimate"));
  s.ground_truth = series_to_isometry(series("ground_truth"));
  s.converged = row.value("converged") > 0.5;
  s.iterations = static_cast<int>(row.value("iterations"));
  s.seconds = row.value("seconds_registration");
  const double input = row.value("input_points"), percent = row.value("matched_percent");
  if (std::isfinite(input) && std::isfinite(percent) && input > 0) {
    s.total_points = static_cast<std::size_t>(input);
    s.matched_points = static_cast<std::size_t>(std::llround(percent / 100.0 * input));
  }
  return s;
}

std::optional<RegistrationSample> odometry_sample_of(const RunRow& row) {
  const auto it = row.series.find("odometry");
  const auto gt = row.series.find("ground_truth");
  if (it == row.series.end() || gt == row.series.end()) return std::nullopt;
  RegistrationSample s;
  s.estimate = series_to_isometry(it->second);
  s.ground_truth = series_to_isometry(gt->second);
  return s;
}

RegistrationStatsSettings stats_settings(const RegistrationParams& params) {
  RegistrationStatsSettings s;
  s.axes = params.axes;
  s.success = thesis_success_criterion(params.success);
  return s;
}

ParameterReference read_parameter_reference(const YAML::Node& node, const std::string& file) {
  ParameterReference r;
  if (!node.IsMap()) return r;
  r.mean = read_six(node, file, "mean");
  r.std = read_six(node, file, "std");
  r.max = read_six(node, file, "max");
  return r;
}

YAML::Node child_or_null(const YAML::Node& node, const std::string& key) {
  if (!node.IsDefined() || !node.IsMap()) return YAML::Node();
  const YAML::Node child = node[key];
  return child.IsDefined() ? child : YAML::Node();
}

std::optional<double> reference_number(const YAML::Node& node, const std::string& key) {
  if (!node.IsMap() || !node[key].IsDefined() || node[key].IsNull()) return std::nullopt;
  return node[key].as<double>();
}

Cell number_or_missing(double value, int precision) {
  return std::isfinite(value) ? Cell::number(value, precision) : Cell::missing();
}

Cell number_or_missing(const std::optional<double>& value, int precision) {
  return value ? number_or_missing(*value, precision) : Cell::missing();
}

std::string format_number(double value, int precision) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", precision, value);
  return buffer;
}

void check_registration_reference(const ExperimentConfig& config, const RegistrationParams& params) {
  if (params.report == RegistrationLayout::kBasin) {
    (void)read_basin_report_settings(config);
    return;
  }
  SettingsReader in(config.reference, config.file);
  switch (params.report) {
    case RegistrationLayout::kAccuracy: {
      const YAML::Node odometry = in.child("odometry");
      if (odometry.IsDefined() && !odometry.IsNull()) check_accuracy_method(odometry, config.file);
      check_map_of(in.child("methods"), config.file, "methods", check_accuracy_method);
      break;
    }
    case RegistrationLayout::kBasin: break;  // read_basin_report_settings, above
    case RegistrationLayout::kInitLayer:
      check_map_of(in.child("table_5_8"), config.file, "table_5_8", check_layer_row);
      check_map_of(in.child("guideline"), config.file, "guideline", check_guideline);
      break;
    case RegistrationLayout::kSampling: {
      check_map_of(in.child("methods"), config.file, "methods", check_accuracy_method);
      check_map_of(in.child("table_5_7"), config.file, "table_5_7", check_sampling_row);
      break;
    }
    case RegistrationLayout::kStrategies: {
      check_map_of(in.child("table_5_9"), config.file, "table_5_9", check_strategy_row);
      SettingsReader sampling(in.child("sampling_seconds"), config.file);
      SettingsReader below(in.child("mean_error_below"), config.file);
      double x = 0;
      for (const char* key : {"fbs", "gbs"}) sampling.read(key, x);
      for (const char* key : {"translation_cm", "rotation_deg"}) below.read(key, x);
      sampling.finish();
      below.finish();
      break;
    }
    case RegistrationLayout::kZeroGuess: {
      double x = 0;
      for (const char* key : {"iterations", "error_cm"}) in.read(key, x);
      break;
    }
  }
  in.finish();
}

}  // namespace sextant
