#pragma once
// `sextant report`: reads one or more result folders (a results root with one folder per
// experiment, shards included), and writes per experiment Markdown, LaTeX and CSV tables and SVG
// figures, 3D views (HTML pages sharing one three.min.js in the output folder), plus an index.html
// showing every table, figure, link to a 3D view, claim verdict and the provenance.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace sextant {

struct ReportSummary {
  std::size_t experiments = 0;
  std::size_t tables = 0;
  std::size_t figures = 0;
  std::size_t views = 0;  ///< interactive 3D pages (<experiment>/<id>.html)
  std::size_t claims = 0;
  std::filesystem::path index_html;
  std::vector<std::string> failed;  ///< "<experiment>: <error>" for each experiment whose report failed
};

/// `results` are results roots (each holding <experiment>/experiment.yaml and runs.jsonl).
/// Rows of the same experiment found in several roots are merged by run key. `out` is written as a
/// whole (OutputFolder): a rerun replaces every file of the earlier report.
ReportSummary write_report(const std::vector<std::filesystem::path>& results,
                           const std::filesystem::path& out);

/// What a merge wrote, per experiment: its rows, and the runs of its config that no input has
/// (by name) or that more than one input has (by count).
struct MergedExperiment {
  std::string name;
  std::size_t inputs = 0;                 ///< distinct folders merged (the target's own included)
  std::size_t rows = 0;                   ///< rows written to runs.jsonl
  std::size_t expected = 0;               ///< runs of the config
  std::size_t missing = 0;                ///< runs of the config without a successful row
  std::size_t duplicated = 0;             ///< runs with a row in more than one input
  std::vector<std::string> missing_runs;  ///< "method, axis = value, repetition r" of each missing run
};
struct MergeSummary {
  std::size_t rows = 0;
  std::vector<MergedExperiment> experiments;
};

/// `sextant merge`: combines result roots (e.g. one per shard) into `out`: runs.jsonl deduplicated
/// by key, runs.csv, experiment.yaml, and every provenance file. Holds each target folder's results
/// lock (a running `sextant run` or merge there makes it an InputError), keeps the rows already in
/// the target, counts a folder named twice once, and refuses inputs whose experiment.yaml differs.
MergeSummary merge_results(const std::vector<std::filesystem::path>& inputs,
                           const std::filesystem::path& out);

}  // namespace sextant
