#pragma once
// Experiment YAML for the experiments tests (temporary folders: sextant_test/temp_dir.hpp).
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "sextant_test/temp_dir.hpp"

namespace sextant::test {

/// A selftest experiment with `points` sweep values × 2 methods × `reps` repetitions.
inline std::string selftest_yaml(const std::string& name, int points, int reps, int sleep_ms) {
  return "name: " + name + "\nkind: selftest\nrepetitions: " + std::to_string(reps) +
         "\nseed: 7\nmethods:\n  - name: a\n  - name: b\nsweep:\n  x: {from: 1, to: " +
         std::to_string(points) + "}\nparams:\n  sleep_ms: " + std::to_string(sleep_ms) + "\n";
}

}  // namespace sextant::test
