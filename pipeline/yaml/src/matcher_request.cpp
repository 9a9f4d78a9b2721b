// The matcher and sampler a user asks for, read once (matcher_request.hpp).
#include "sextant/pipeline/matcher_request.hpp"

#include <algorithm>
#include <vector>

#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/matchers/matcher_traits.hpp"
#include "sextant/matchers/optimizer_settings.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant {
namespace {

/// Appends "prefix.key value" for every scalar of `given` that `defaults` lacks or holds differently,
/// and "prefix.key" for every key of `defaults` that `given` lacks. `threads` never changes a result
/// (mlndt_matcher.hpp): it is not compared.
void differing_keys(const YAML::Node& given, const YAML::Node& defaults, const std::string& prefix,
                    std::vector<std::string>& out) {
  if (given.IsMap() && defaults.IsMap()) {
    for (const auto& entry : given) {
      const std::string key = entry.first.as<std::string>();
      if (key == "threads") continue;
      differing_keys(entry.second, defaults[key], prefix + "." + key, out);
    }
    for (const auto& entry : defaults)
      if (entry.first.as<std::string>() != "threads" && !given[entry.first.as<std::string>()].IsDefined())
        out.push_back(prefix + "." + entry.first.as<std::string>());
    return;
  }
  if (!defaults.IsDefined() || YAML::Dump(given) != YAML::Dump(defaults))
    out.push_back(prefix + " " + YAML::Dump(given));
}

}  // namespace

MatcherConfig read_matcher_config(const MatcherRequest& r, Face face, bool wide_basin) {
  MatcherConfig config;
  config.request = r;
  config.matcher = r.matcher.IsMap() ? YAML::Clone(r.matcher) : YAML::Node(YAML::NodeType::Map);
  if (r.sampler.IsDefined() && !r.sampler.IsNull()) config.sampler = YAML::Clone(r.sampler);
  const bool presets = matcher_traits(r.method).has_presets;
  if (!r.preset.empty() && !presets)
    throw InputError(argument(face, "preset"), "",
                     "presets are settings of mlndt and fbmlndt, not of '" + r.method + "'");
  // The settings' own `preset:` wins over the argument; their other keys override the preset's.
  if (presets && !config.matcher["preset"].IsDefined())
    config.matcher["preset"] = r.preset.empty() ? "default" : r.preset;
  if (!r.preset.empty()) {
    const std::vector<std::string> names = mlndt_preset_names();
    if (std::find(names.begin(), names.end(), r.preset) == names.end()) {
      std::string known;
      for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
      throw InputError(argument(face, "preset"), "",
                       "unknown preset '" + r.preset + "' (known: " + known + ")");
    }
  }
  if (!r.solver.empty()) {
    SolverKind kind;
    if (!presets)
      throw InputError(argument(face, "solver"), "",
                       "a solver is a setting of mlndt and fbmlndt, not of '" + r.method + "'");
    if (!from_string(r.solver, &kind))
      throw InputError(argument(face, "solver"), "",
                       "unknown solver '" + r.solver + "' (known: newton, lm, ceres)");
    config.matcher["solver"] = r.solver;
  }
  if (wide_basin && matcher_traits(r.method).has_wide_basin && !config.matcher["wide_basin"].IsDefined())
    config.matcher["wide_basin"] = YAML::Node(YAML::NodeType::Map);
  config.preset = presets ? config.matcher["preset"].as<std::string>("") : "";
  config.resolved = YAML::Node(YAML::NodeType::Map);
  {
    SettingsRecording recording;
    config.spec.matcher = read_matcher_spec(r.method, config.matcher, r.matcher_where);
    config.resolved["matcher"] = YAML::Clone(recording.resolved());
  }
  {
    SettingsRecording recording;
    config.spec.sampler = read_sampler_spec(r.sampling, config.sampler, r.sampler_where);
    config.resolved["sampler"] = YAML::Clone(recording.resolved());
  }
  return config;
}

std::vector<std::string> settings_off_the_defaults(const MatcherConfig& config) {
  const MatcherRequest& o = config.request;
  const YAML::Node& resolved = config.resolved;
  const MatcherRequest plain;
  if (o.method != plain.method) return {"method " + o.method};
  const YAML::Node defaults = read_matcher_config(plain, Face::cli).resolved;
  std::vector<std::string> out;
  differing_keys(resolved["matcher"], defaults["matcher"], "matcher", out);
  if (o.sampling != plain.sampling)
    out.push_back("sampling " + o.sampling);  // another sampler: its settings compare with nothing
  else
    differing_keys(resolved["sampler"], defaults["sampler"], "sampler", out);
  return out;
}

std::string uncalibrated_trust_note(const std::vector<std::string>& differences) {
  if (differences.empty()) return "";
  std::string list;
  for (const std::string& d : differences) list += (list.empty() ? "" : ", ") + d;
  return "the trust checks' thresholds were measured with the default settings; this run differs (" + list +
         "), and outside the defaults some settings let wrong registrations pass as trusted "
         "(docs/matcher_defaults.md, \"The choice\")";
}

std::string describe_matcher(const MatcherConfig& config) {
  const MatcherRequest& r = config.request;
  return r.method + (config.preset.empty() ? "" : " (preset " + config.preset + ")") +
         (r.solver.empty() ? "" : " (solver " + r.solver + ")");
}

}  // namespace sextant
