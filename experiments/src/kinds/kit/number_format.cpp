#include "kit/number_format.hpp"

#include <cmath>
#include <cstdio>

namespace sextant {

std::string format_number(double value, int precision, const char* if_not_finite) {
  if (if_not_finite && !std::isfinite(value)) return if_not_finite;
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", precision, value);
  return buffer;
}

Cell number_or_missing(double value, int precision) {
  return std::isfinite(value) ? Cell::number(value, precision) : Cell::missing();
}

Cell number_or_missing(const std::optional<double>& value, int precision) {
  return value ? number_or_missing(*value, precision) : Cell::missing();
}

}  // namespace sextant
