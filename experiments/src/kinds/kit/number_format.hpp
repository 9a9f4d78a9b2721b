#pragma once
// How the reports show a number: as text in notes and claims, or as a table cell.
#include <optional>
#include <string>

#include "sextant/eval/table.hpp"

namespace sextant {

/// `value` with `precision` decimals ("%.*f"). A NaN or infinite value is `if_not_finite` when that
/// is given, else printf's "nan" / "inf".
std::string format_number(double value, int precision = 2, const char* if_not_finite = nullptr);

/// A number cell, or a missing cell for NaN, ±inf and nullopt.
Cell number_or_missing(double value, int precision = -1);
Cell number_or_missing(const std::optional<double>& value, int precision = -1);

}  // namespace sextant
