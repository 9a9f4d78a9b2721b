#pragma once
// Tables laid out like the thesis' tables 5.1–5.6: rows Mean / Std / Max, columns tx, ty, tz [cm]
// and α, β, γ [deg], each as an "ours | thesis" pair; thesis values the thesis does not give
// (e.g. "n/a" in table 5.1) stay missing.
#include <array>
#include <optional>
#include <string>

#include "sextant/eval/registration_metrics.hpp"
#include "sextant/eval/table.hpp"

namespace sextant {

/// The thesis' printed mean / std / max per parameter (tx, ty, tz, α, β, γ); nullopt = not given.
struct ParameterReference {
  std::array<std::optional<double>, 6> mean, std, max;
};

/// `thesis` may be null (then every thesis column is missing). Column headers use
/// parameter_names(); translations with 2 decimals, angles with 2.
Table registration_error_table(const RegistrationStats& ours, const ParameterReference* thesis,
                               const std::string& caption, const std::string& label = "");

}  // namespace sextant
