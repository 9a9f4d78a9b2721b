#pragma once
// What each method of a registration experiment does differently from the thesis, read from its
// settings (not typed in): solver and step control, the LM residual form, the unmatched-point
// penalty, truncation, start layer, trilinear interpolation. The layouts print it in one place.
#include <string>
#include <vector>

#include "registration/settings.hpp"

namespace sextant {

/// One line per method: "name: deviation; deviation" (or "as in the thesis").
std::string method_deviations(const RegistrationMethod& method);
/// All methods of the config, one per line, with a heading.
std::string deviations_note(const ExperimentConfig& config);

}  // namespace sextant
