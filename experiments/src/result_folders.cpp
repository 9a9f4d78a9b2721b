#include "result_folders.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "sextant/core/error.hpp"
#include "sextant/core/log.hpp"
#include "sextant/experiments/runner.hpp"

namespace sextant::detail {

namespace fs = std::filesystem;

/// experiment name → its result folders (one per results root that has it).
std::map<std::string, std::vector<fs::path>> find_experiments(const std::vector<fs::path>& roots) {
  std::map<std::string, std::vector<fs::path>> found;
  for (const auto& root : roots) {
    if (!fs::is_directory(root)) throw InputError(root.string(), "", "not a results folder");
    if (fs::exists(root / kEffectiveConfig)) {  // a single experiment's folder given directly
      found[root.filename().string()].push_back(root);
      continue;
    }
    for (const auto& entry : fs::directory_iterator(root)) {
      if (entry.is_directory() && fs::exists(entry.path() / kEffectiveConfig))
        found[entry.path().filename().string()].push_back(entry.path());
    }
  }
  return found;
}

/// Rows of all folders, one per key; a successful row beats a failed one.
/// Unreadable lines are skipped, each named (file:line) in `warnings` and logged. `shared_keys`
/// counts the keys that more than one folder holds.
std::vector<RunRow> union_rows(const std::vector<fs::path>& folders, std::vector<std::string>* warnings,
                               std::size_t* shared_keys) {
  std::vector<RunRow> rows;
  std::unordered_map<std::string, std::size_t> position;
  std::vector<std::size_t> first_folder;  // per row: the folder it was first found in
  std::vector<bool> shared;               // per row: found in another folder too
  for (std::size_t f = 0; f < folders.size(); ++f) {
    RowFile file = read_rows(folders[f] / kRunsJsonl);
    for (const auto& message : bad_line_messages(folders[f] / kRunsJsonl, file)) {
      log_warning(message);
      if (warnings) warnings->push_back(message);
    }
    for (auto& row : file.rows) {
      const auto it = position.find(row.key);
      if (it == position.end()) {
        position[row.key] = rows.size();
        rows.push_back(std::move(row));
        first_folder.push_back(f);
        shared.push_back(false);
        continue;
      }
      if (first_folder[it->second] != f) shared[it->second] = true;
      if (row.ok || !rows[it->second].ok) rows[it->second] = std::move(row);
    }
  }
  if (shared_keys) *shared_keys = static_cast<std::size_t>(std::count(shared.begin(), shared.end(), true));
  return rows;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<fs::path> provenance_files(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("provenance", 0) == 0 && entry.path().extension() == ".json")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace sextant::detail
