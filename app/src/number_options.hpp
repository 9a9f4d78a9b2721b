#pragma once
// Numbers users type are checked like numbers in files: every numeric option of every subcommand
// takes one of these validators, so that a value the run cannot honour is a one-line usage error
// naming the option (not a wrapped-around "-1", a 309-digit range, an endless run or an abort).
#include <cstdint>
#include <limits>

#include <CLI/CLI.hpp>

namespace sextant::cli {

/// A whole number in [min, max], written without a sign: "-1" is refused, not read as 2⁶⁴ − 1,
/// and a number past `max` is refused, not clamped.
CLI::Validator whole_number(std::uint64_t min = 0,
                            std::uint64_t max = std::numeric_limits<std::uint64_t>::max());
/// A finite number ≥ min (> min when `strictly`): not nan, inf, or a number past a double's range.
CLI::Validator finite_number(double min, bool strictly = false);
/// Worker threads: 0 (every core) up to max_worker_threads() (core/threads.hpp).
CLI::Validator worker_threads();

}  // namespace sextant::cli
