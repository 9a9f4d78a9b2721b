#include <string>

#include "sextant/core/dataset.hpp"

namespace sextant {

std::string dropped_points_note(const ScanLoadReport& report) {
  if (report.dropped() == 0) return "";
  return std::to_string(report.dropped()) + " of " + std::to_string(report.points_read) +
         " points dropped (" + std::to_string(report.non_finite_dropped) + " non-finite, " +
         std::to_string(report.no_return_dropped) + " no-return)";
}

}  // namespace sextant
