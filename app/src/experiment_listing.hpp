#pragma once
// `sextant info experiments/` (or one experiment YAML): which experiment runs which kind and report
// layout, from the configs themselves, so that no hand-kept list can disagree with them.
// `--markdown` prints the same as the table docs/experiments.md carries (a test keeps it in step).
#include <filesystem>
#include <string>
#include <vector>

namespace sextant::cli {

/// Whether `path` is an experiment YAML or a folder holding eNN_*.yaml files.
bool holds_experiments(const std::filesystem::path& path);

/// Prints one line per experiment: name, kind, layout, thesis section, methods, runs (full, quick).
void describe_experiments(const std::filesystem::path& path, bool markdown);

}  // namespace sextant::cli
