#pragma once
// The ML-NDT settings presets as plain settings: a C++ user asks for `thesis` without yaml-cpp, and a
// YAML map's `preset:` starts from the same struct (its other keys override the preset's).
//
//   default — the measured best on real and synthetic pairs from the guess a user has, and on the
//             benchmark sequences (docs/matcher_defaults.md, "The choice"): the library's defaults
//             (MlndtSettings{}: LM, q = 8, n = 4, s = 2, last-layer terms truncated at 16, unmatched
//             points charged 16) on every thread TBB allows (the result is the same for any count)
//   thesis  — the thesis' exact settings (Table 3.1, §5.1): Newton with the step as printed (eq. 3.16
//             with H + γI, no step control), q = 8, n = 4, s = 2, three iterations per layer, the
//             plain sum of eq. 3.11, unmatched points charged 50 (the thesis leaves that open), the
//             bounding box, no precision stage, no refine_first
//   outdoor — large outdoor scans: the default with n = 6 over the bounding box
#include <optional>
#include <string>
#include <vector>

#include "sextant/matchers/mlndt_matcher.hpp"

namespace sextant {

/// "default", "thesis", "outdoor".
std::vector<std::string> mlndt_preset_names();

/// The preset named `name`; none for another name.
std::optional<MlndtSettings> mlndt_preset(const std::string& name);

}  // namespace sextant
