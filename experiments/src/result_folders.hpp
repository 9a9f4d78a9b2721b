#pragma once
// Reading result roots, shared by the report and the merge: which experiments they hold, the union
// of their rows, and their provenance files.
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "sextant/experiments/run_row.hpp"

namespace sextant::detail {

/// experiment name → its result folders (one per results root that has it).
std::map<std::string, std::vector<std::filesystem::path>> find_experiments(
    const std::vector<std::filesystem::path>& roots);

/// Rows of all folders, one per key; a successful row beats a failed one. Unreadable lines are
/// skipped, each named (file:line) in `warnings` and logged. `shared_keys` counts the keys that more
/// than one folder holds.
std::vector<RunRow> union_rows(const std::vector<std::filesystem::path>& folders,
                               std::vector<std::string>* warnings = nullptr,
                               std::size_t* shared_keys = nullptr);

/// The whole file as bytes.
std::string read_text(const std::filesystem::path& path);

/// provenance*.json of a result folder, sorted.
std::vector<std::filesystem::path> provenance_files(const std::filesystem::path& folder);

}  // namespace sextant::detail
