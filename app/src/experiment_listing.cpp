#include "experiment_listing.hpp"

#include <iomanip>
#include <iostream>

#include "sextant/experiments/experiment_config.hpp"
#include "sextant/experiments/run_plan.hpp"

namespace sextant::cli {
namespace {

namespace fs = std::filesystem;

/// The report layout a config asks its kind for: params.report (or a kind's own word for it:
/// study, model); "-" when the kind has one layout.
std::string layout_of(const ExperimentConfig& c) {
  for (const char* key : {"report", "study", "model"})
    if (c.params && c.params.IsMap() && c.params[key] && c.params[key].IsScalar())
      return c.params[key].as<std::string>();
  return "-";
}

std::vector<fs::path> configs_at(const fs::path& path) {
  if (fs::is_directory(path)) return list_experiment_configs(path);
  return {path};
}

}  // namespace

bool holds_experiments(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return !list_experiment_configs(path).empty();
  const std::string ext = path.extension().string();
  return ext == ".yaml" || ext == ".yml";
}

void describe_experiments(const fs::path& path, bool markdown) {
  if (markdown)
    std::cout << "| experiment | kind | layout | thesis | methods | runs (full / quick) |\n"
                 "|---|---|---|---|---|---|\n";
  for (const fs::path& file : configs_at(path)) {
    const ExperimentConfig full = read_experiment_config(file, false);
    const ExperimentConfig quick = read_experiment_config(file, true);
    const std::size_t runs = expand_runs(full).size(), quick_runs = expand_runs(quick).size();
    if (markdown) {
      std::cout << "| `" << full.name << "` | " << full.kind << " | " << layout_of(full) << " | "
                << full.thesis << " | " << full.methods.size() << " | " << runs << " / " << quick_runs
                << " |\n";
    } else {
      std::cout << std::left << std::setw(38) << full.name << std::setw(16) << full.kind << std::setw(16)
                << layout_of(full) << std::setw(5) << full.methods.size() << std::right << std::setw(6)
                << runs << " /" << std::setw(5) << quick_runs << "  " << full.thesis << "\n";
    }
  }
}

}  // namespace sextant::cli
