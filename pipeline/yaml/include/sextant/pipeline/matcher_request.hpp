#pragma once
// The matcher and sampler a user asks for, as both faces take them (`sextant match` / `sextant
// odometry`: --method, --preset, --solver, --sampling, --config; sextant.match() / sextant.odometry():
// method=, preset=, sampling=, the settings keywords), read once into specs (matcher_spec.hpp).
//
// The preset rule, one for every face: mlndt and fbmlndt start from `preset: <preset or "default">`
// unless their settings name their own (which wins; their other keys override the preset's); a
// preset, or a solver, for another matcher is an InputError naming the argument.
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "sextant/matchers/matcher_spec.hpp"
#include "sextant/pipeline/odometry_request.hpp"

namespace sextant {

struct MatcherRequest {
  std::string method = "mlndt";
  std::string preset;  ///< empty: "default" for a matcher with presets
  std::string solver;  ///< empty: the preset's
  std::string sampling = "gbs";
  YAML::Node matcher;                              ///< the matcher's settings map as given; null: none
  YAML::Node sampler;                              ///< the sampler's; null: its defaults
  std::string matcher_where = "matcher settings";  ///< named in the settings' errors (a file, the arguments)
  std::string sampler_where = "sampler settings";
};

/// What a request reads into: the settings as given (with the preset applied) and the specs.
struct MatcherConfig {
  MatcherRequest request;  ///< what was asked for
  YAML::Node matcher;      ///< a map (mlndt/fbmlndt: with `preset:`)
  YAML::Node sampler;      ///< may be null
  std::string preset;      ///< the preset in effect ("" for a matcher without presets)
  RegistrationSpec spec;
  /// Every setting the specs hold, the given ones and the defaults they keep (SettingsRecording):
  /// {matcher: {…}, sampler: {…}}
  YAML::Node resolved;
};

/// Reads `request` (InputError naming the argument or the settings' file, line and key). `wide_basin`:
/// with the wide basin on (`wide_basin: {}` unless the settings have their own), for a matcher with one.
MatcherConfig read_matcher_config(const MatcherRequest& request, Face face, bool wide_basin = false);

/// "mlndt (preset default)", "icp_p2l (solver lm)", …
std::string describe_matcher(const MatcherConfig& config);

/// The settings in which the config's `resolved` differs from what a run with no
/// arguments uses (mlndt, the `default` preset, GBS at its defaults), as "matcher.layers 5",
/// "sampler.cell_size 0.5", "method icp_p2l"; empty for the defaults. The trust checks' thresholds
/// were measured with the defaults (docs/matcher_defaults.md), so the faces say when a run is outside them.
std::vector<std::string> settings_off_the_defaults(const MatcherConfig& config);

/// The note the faces print for those differences ("" when there are none).
std::string uncalibrated_trust_note(const std::vector<std::string>& differences);

}  // namespace sextant
