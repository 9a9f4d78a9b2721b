// The per-point time field of a lidar record and its conversion to seconds (point_time.hpp).
#include "sextant/core/io/point_time.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sextant {
namespace {

constexpr double kEpochSeconds = 1e8;     // beyond this, a time is since the epoch (1973 on)
constexpr double kLargestSeconds = 1e11;  // beyond this, seconds since the epoch are nanoseconds

double largest_magnitude(const std::vector<double>& raw) {
  double largest = 0.0;
  for (double v : raw)
    if (std::isfinite(v)) largest = std::max(largest, std::abs(v));
  return largest;
}

}  // namespace

const std::vector<std::string>& point_time_field_names() {
  static const std::vector<std::string> names{"t", "time", "timestamp", "offset_time", "time_offset", "ts"};
  return names;
}

std::optional<std::size_t> find_point_time_field(const std::vector<std::string>& field_names) {
  for (const std::string& wanted : point_time_field_names()) {
    const auto it = std::find(field_names.begin(), field_names.end(), wanted);
    if (it != field_names.end()) return static_cast<std::size_t>(it - field_names.begin());
  }
  return std::nullopt;
}

std::vector<float> point_times_to_seconds(const std::vector<double>& raw, bool integer_field,
                                          std::optional<double> stamp, PointTimeConversion* how) {
  PointTimeConversion conversion;
  const double largest = largest_magnitude(raw);
  conversion.seconds_per_unit = integer_field || largest > kLargestSeconds ? 1e-9 : 1.0;
  conversion.absolute = largest * conversion.seconds_per_unit > kEpochSeconds;
  double origin = 0.0;  // in raw units
  if (conversion.absolute) {
    if (stamp) {
      origin = *stamp / conversion.seconds_per_unit;
    } else {
      origin = std::numeric_limits<double>::infinity();
      for (double v : raw)
        if (std::isfinite(v)) origin = std::min(origin, v);
    }
  }
  std::vector<float> seconds;
  seconds.reserve(raw.size());
  for (double v : raw) seconds.push_back(static_cast<float>((v - origin) * conversion.seconds_per_unit));
  if (how) *how = conversion;
  return seconds;
}

}  // namespace sextant
