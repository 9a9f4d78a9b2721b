#include "matcher_options.hpp"

#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"

namespace sextant::cli {
namespace {

bool ndt_family(const std::string& method) {
  return method == "mlndt" || method == "fbmlndt";
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
  if (!o.preset.empty() && !ndt_family(o.method))
    throw InputError("--preset", "", "presets are settings of mlndt and fbmlndt, not of '" + o.method + "'");
  // The --config file's own `preset:` wins over --preset; its other keys override the preset's.
  if (ndt_family(o.method) && config.matcher.IsMap() && !config.matcher["preset"].IsDefined())
    config.matcher["preset"] = o.preset.empty() ? "default" : o.preset;
  if (!o.solver.empty()) config.matcher["solver"] = o.solver;
  return config;
}

std::string describe_matcher(const MatcherOptions& o) {
  return o.method +
         (ndt_family(o.method)
              ? " (preset " + (o.preset.empty() ? std::string("default") : o.preset) + o.preset_note + ")"
              : "") +
         (o.solver.empty() ? "" : " (solver " + o.solver + ")");
}

}  // namespace sextant::cli
