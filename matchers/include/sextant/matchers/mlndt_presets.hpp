#pragma once
// Named settings of the `mlndt` matcher (and `fbmlndt`, which forwards the mlndt keys). A YAML map
// may say `preset: <name>`; its other keys override the preset's. One rule everywhere: `default`
// unless a preset is named (`sextant match`, `sextant odometry`, the Python module, the library).
//
//   default — the measured best over every shared real pair and three campus pairs from the guess a
//             user has (bench/bench_matcher_defaults, docs/matcher_defaults.md): LM, q = 8, n = 4,
//             s = 2, last-layer terms truncated at 16 (unmatched points charged 16), with GBS input;
//             also the library's defaults (MlndtSettings{}, a settings map without `preset:`)
//   thesis  — the thesis' exact settings (Table 3.1, §5.1): Newton with the step as printed (eq. 3.16
//             with H + γI, no step control), q = 8, n = 4, s = 2, three iterations per layer, the
//             plain sum of eq. 3.11, unmatched points charged 50 (every experiment config of the
//             thesis' nineteen says `preset: thesis` and overrides what it deliberately changes,
//             which its report section names)
//   outdoor — large outdoor scans: the default with n = 6 (finest cells ≈ 0.6–1 m on 100 m scenes)
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace sextant {

/// The preset's settings map; InputError (naming `file`) for an unknown name.
YAML::Node mlndt_preset(const std::string& name, const std::string& file = "<settings>");
std::vector<std::string> mlndt_preset_names();

/// `settings` (mlndt or fbmlndt) with the wide basin switched on (`wide_basin: {}` unless it has its
/// own); nothing for a matcher without a wide basin.
std::optional<YAML::Node> with_wide_basin(const std::string& matcher, const YAML::Node& settings);

/// `settings` with its `preset:` key (if any) expanded: the preset's keys, overridden by the others.
YAML::Node expand_mlndt_preset(const YAML::Node& settings, const std::string& file);

}  // namespace sextant
