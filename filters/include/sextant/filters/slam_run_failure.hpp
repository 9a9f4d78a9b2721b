#pragma once
// When a SLAM run is no result: a filter that mapped nothing, or that failed (a non-ok status:
// not positive definite, a failed Cholesky, a singular innovation) on more than half of its
// steps, has no trajectory worth scoring. Its run is a failed run, never an `ok` row.
#include <cstddef>
#include <string>

namespace sextant {

/// Why the run is no result, or an empty string when it is one.
inline std::string slam_run_failure(std::size_t mapped_landmarks, std::size_t failed_steps,
                                    std::size_t steps) {
  if (steps > 0 && mapped_landmarks == 0) return "the filter mapped no landmark";
  if (2 * failed_steps > steps)
    return "the filter failed " + std::to_string(failed_steps) + " of " + std::to_string(steps) + " steps";
  return {};
}

}  // namespace sextant
