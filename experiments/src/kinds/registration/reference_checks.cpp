// What the registration layouts' reference checks share (each layout's check of its `reference:`
// block is in its own file, named in the table of registration/layouts/layouts.cpp): the thesis'
// per-parameter numbers, a map of blocks, an accuracy method's block.
#include <array>
#include <optional>

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

}  // namespace

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

ParameterReference read_parameter_reference(const YAML::Node& node, const std::string& file) {
  ParameterReference r;
  if (!node.IsMap()) return r;
  r.mean = read_six(node, file, "mean");
  r.std = read_six(node, file, "std");
  r.max = read_six(node, file, "max");
  return r;
}

}  // namespace sextant
