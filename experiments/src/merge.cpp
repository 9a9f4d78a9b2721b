// sextant merge: the result folders of shards (and the target's own rows) combined into one,
// under the results lock, never dropping a row, refusing two configs, counting missing and duplicated runs.
#include <set>

#include "result_folders.hpp"
#include "results_lock.hpp"
#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/experiments/report.hpp"
#include "sextant/experiments/runner.hpp"

namespace sextant {

MergeSummary merge_results(const std::vector<std::filesystem::path>& inputs,
                           const std::filesystem::path& out) {
  namespace fs = std::filesystem;
  using detail::provenance_files, detail::read_text;
  MergeSummary summary;
  for (auto [name, folders] : detail::find_experiments(inputs)) {
    const fs::path dir = out / name;
    const detail::ResultsLock lock(dir);  // no runner and no other merge writes here meanwhile
    // The target's own rows are an input too: a merge never drops what is already there.
    if (fs::exists(dir / kEffectiveConfig)) folders.insert(folders.begin(), dir);
    // The same folder named twice counts once.
    std::vector<fs::path> distinct;
    std::set<fs::path> seen;
    for (const fs::path& f : folders)
      if (seen.insert(fs::weakly_canonical(f)).second) distinct.push_back(f);
    folders = std::move(distinct);
    // Results of two configs are not one experiment: refuse rather than mix them.
    const fs::path config_path = folders.front() / kEffectiveConfig;
    const std::string config_text = read_text(config_path);
    for (const fs::path& f : folders)
      if (read_text(f / kEffectiveConfig) != config_text)
        throw InputError((f / kEffectiveConfig).string(), "",
                         "differs from " + config_path.string() +
                             ": these are results of two configs; merge each config's folders apart");
    const std::vector<RunSpec> runs = expand_runs(
        parse_experiment_config(load_yaml_file(config_path.string()), config_path.string(), false));
    MergedExperiment& merged = summary.experiments.emplace_back();
    merged.name = name;
    merged.inputs = folders.size();
    merged.expected = runs.size();
    // Rows in the expansion order of the config they were run with: the merged files do not depend
    // on how many shards there were or in which order their runs finished.
    const std::vector<RunRow> rows =
        in_expansion_order(detail::union_rows(folders, nullptr, &merged.duplicated), runs);
    std::set<std::string> present;
    for (const RunRow& row : rows)
      if (row.ok) present.insert(row.key);
    for (const RunSpec& run : runs) {
      if (present.count(run.key)) continue;
      ++merged.missing;
      std::string label = run.method;
      for (const auto& [axis, value] : run.point) label += ", " + axis + " = " + value;
      merged.missing_runs.push_back(label + ", repetition " + std::to_string(run.repetition));
    }
    std::string text;
    for (const auto& row : rows) text += to_json_line(row) + "\n";
    write_file_atomically(dir / kRunsJsonl, text);
    write_rows_csv(dir / kRunsCsv, rows);
    write_file_atomically(dir / kEffectiveConfig, config_text);
    std::set<std::string> names;  // provenance files written by this merge
    for (std::size_t k = 0; k < folders.size(); ++k) {
      for (const auto& file : provenance_files(folders[k])) {
        std::string target = file.filename().string();
        if (!names.insert(target).second) {
          target = file.stem().string() + ".input-" + std::to_string(k + 1) + ".json";
          names.insert(target);
        }
        if (fs::weakly_canonical(file) != fs::weakly_canonical(dir / target))
          write_file_atomically(dir / target, read_text(file));
      }
    }
    merged.rows = rows.size();
    summary.rows += rows.size();
  }
  return summary;
}

}  // namespace sextant
