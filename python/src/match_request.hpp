#pragma once
// sextant.match()'s choices: the CLI's preset rule (mlndt/fbmlndt get `preset: <preset or
// "default">` unless the settings name their own; a preset for another matcher is an InputError),
// then register_pair (matchers/register_pair.hpp), the policy `sextant match` runs too: the wide
// basin without a guess, a retry with it of an untrusted result with one.
// No Python here: run_match_request runs with the GIL released.
#include <cstdint>
#include <optional>
#include <string>

#include <yaml-cpp/yaml.h>
#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/matchers/match_pair.hpp"

namespace sextant::python {

struct MatchRequest {
  std::string method = "mlndt";
  std::string preset;  ///< empty: "default" for mlndt/fbmlndt (the CLI's --preset)
  std::string sampling = "gbs";
  YAML::Node settings;          ///< matcher settings map (the CLI's --config `matcher:` and --solver)
  YAML::Node sampler_settings;  ///< null: the sampler's defaults (the CLI's --config `sampler:`)
  std::optional<Eigen::Isometry3d> init;  ///< the CLI's --init; none: the identity, searched
  bool wide_basin_retry = true;           ///< false: the CLI's --no-wide-basin
  std::uint64_t seed = 1;                 ///< the CLI's --seed
};

struct MatchOutcome {
  PairMatch match;
  std::string preset;     ///< the preset applied ("" for matchers without presets)
  bool searched = false;  ///< the result came from the wide basin
  std::string search;     ///< how, in the CLI's words ("wide basin", "from the guess", …)
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< the point registered about (register_pair.hpp)
};

/// The matcher settings `sextant match` and `sextant odometry` build from --method, --preset and
/// the `matcher:` map (the CLI's read_matcher_config): mlndt/fbmlndt get `preset:` unless the map
/// names one; InputError for a preset on a matcher without presets. `applied`: the preset in effect
/// ("" for other matchers).
YAML::Node matcher_settings(const std::string& method, const std::string& preset, const YAML::Node& settings,
                            std::string* applied);

/// Registers `input` against `reference` as `sextant match` does (see above).
MatchOutcome run_match_request(const PointCloud& reference, const PointCloud& input,
                               const MatchRequest& request);

}  // namespace sextant::python
