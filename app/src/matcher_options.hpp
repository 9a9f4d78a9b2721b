#pragma once
// The matcher choice shared by `sextant match` and `sextant odometry`: --method, --preset,
// --solver, --sampling and an optional --config YAML file with `matcher:` and `sampler:` maps.
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace sextant::cli {

struct MatcherOptions {
  std::string method = "mlndt";
  std::string preset;  ///< mlndt / fbmlndt settings preset; empty: "default" (matchers/yaml.hpp)
  std::string solver;  ///< empty: the preset's
  std::string sampling = "gbs";
  std::string config;  ///< YAML file with optional `matcher:` and `sampler:` maps
};

struct MatcherConfig {
  YAML::Node matcher;  ///< a map (mlndt/fbmlndt: with `preset:`)
  YAML::Node sampler;  ///< may be null
};

/// Reads --config, applies --preset (the file's own `preset:` wins; its other keys override the
/// preset's) and --solver. InputError for --preset on a matcher without presets.
MatcherConfig read_matcher_config(const MatcherOptions& o);

/// Every setting the matcher and the sampler run with — the given ones and the defaults they keep
/// (SettingsRecording): {matcher: {…}, sampler: {…}}. Also checks them (InputError naming `where`).
YAML::Node resolved_settings(const MatcherOptions& o, const MatcherConfig& config, const std::string& where);

/// "mlndt (preset default)", "icp_p2l (solver lm)", …
std::string describe_matcher(const MatcherOptions& o);

/// The settings in which `resolved` (resolved_settings of `o`) differs from what the commands run
/// with no options (mlndt, the `default` preset, GBS at its defaults), as "matcher.layers 5",
/// "sampler.cell_size 0.5", "method icp_p2l"; empty for the defaults. The trust checks' thresholds
/// were measured with the defaults (docs/matcher_defaults.md), so the commands say when they run
/// outside them.
std::vector<std::string> settings_off_the_defaults(const MatcherOptions& o, const YAML::Node& resolved);

/// The note the commands print for those differences ("" when there are none).
std::string uncalibrated_trust_note(const std::vector<std::string>& differences);

}  // namespace sextant::cli
