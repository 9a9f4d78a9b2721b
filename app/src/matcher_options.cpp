#include "matcher_options.hpp"

#include <algorithm>
#include <vector>

#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/matcher_traits.hpp"
#include "sextant/matchers/optimizer.hpp"
#include "sextant/matchers/sampler.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant::cli {
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

MatcherConfig read_matcher_config(const MatcherOptions& o) {
  MatcherConfig config;
  if (!o.config.empty()) {
    SettingsReader in(load_yaml_file(o.config), o.config);
    config.matcher = in.child("matcher");
    config.sampler = in.child("sampler");
    in.finish();
  }
  if (!config.matcher.IsDefined() || config.matcher.IsNull())
    config.matcher = YAML::Node(YAML::NodeType::Map);
  if (!o.preset.empty() && !matcher_traits(o.method).has_presets)
    throw InputError("--preset", "", "presets are settings of mlndt and fbmlndt, not of '" + o.method + "'");
  // The --config file's own `preset:` wins over --preset; its other keys override the preset's.
  if (matcher_traits(o.method).has_presets && config.matcher.IsMap() && !config.matcher["preset"].IsDefined())
    config.matcher["preset"] = o.preset.empty() ? "default" : o.preset;
  if (!o.preset.empty()) {
    const std::vector<std::string> names = mlndt_preset_names();
    if (std::find(names.begin(), names.end(), o.preset) == names.end()) {
      std::string known;
      for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
      throw InputError("--preset", "", "unknown preset '" + o.preset + "' (known: " + known + ")");
    }
  }
  if (!o.solver.empty()) {
    SolverKind kind;
    if (!matcher_traits(o.method).has_presets)
      throw InputError("--solver", "",
                       "a solver is a setting of mlndt and fbmlndt, not of '" + o.method + "'");
    if (!from_string(o.solver, &kind))
      throw InputError("--solver", "", "unknown solver '" + o.solver + "' (known: newton, lm, ceres)");
    config.matcher["solver"] = o.solver;
  }
  return config;
}

YAML::Node resolved_settings(const MatcherOptions& o, const MatcherConfig& config, const std::string& where) {
  YAML::Node out(YAML::NodeType::Map);
  {
    SettingsRecording recording;
    (void)make_matcher(o.method, config.matcher, where);
    out["matcher"] = YAML::Clone(recording.resolved());
  }
  {
    SettingsRecording recording;
    (void)make_sampler(o.sampling, config.sampler,
                       o.config.empty() ? "sampler settings (--sampling)" : o.config);
    out["sampler"] = YAML::Clone(recording.resolved());
  }
  return out;
}

std::vector<std::string> settings_off_the_defaults(const MatcherOptions& o, const YAML::Node& resolved) {
  const MatcherOptions plain;
  if (o.method != plain.method) return {"method " + o.method};
  const YAML::Node defaults = resolved_settings(plain, read_matcher_config(plain), "the defaults");
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

std::string describe_matcher(const MatcherOptions& o) {
  return o.method +
         (matcher_traits(o.method).has_presets
              ? " (preset " + (o.preset.empty() ? std::string("default") : o.preset) + ")"
              : "") +
         (o.solver.empty() ? "" : " (solver " + o.solver + ")");
}

}  // namespace sextant::cli
