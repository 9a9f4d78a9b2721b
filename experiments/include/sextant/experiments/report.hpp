#pragma once
// `sextant report`: reads one or more result folders (a results root with one folder per
// experiment, shards included), and writes per experiment Markdown, LaTeX and CSV tables and SVG
// figures, plus an index.html showing every table, figure, claim verdict and the provenance.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace sextant {

struct ReportSummary {
  std::size_t experiments = 0;
  std::size_t tables = 0;
  std::size_t figures = 0;
  std::size_t claims = 0;
  std::filesystem::path index_html;
  std::vector<std::string> failed;  ///< "<experiment>: <error>" for each experiment whose report failed
};

/// `results` are results roots (each holding <experiment>/experiment.yaml and runs.jsonl).
/// Rows of the same experiment found in several roots are merged by run key.
ReportSummary write_report(const std::vector<std::filesystem::path>& results,
                           const std::filesystem::path& out);

/// `sextant merge`: combines result roots (e.g. one per shard) into `out`: runs.jsonl deduplicated
/// by key, runs.csv, experiment.yaml, and every provenance file. Returns the number of rows written.
std::size_t merge_results(const std::vector<std::filesystem::path>& inputs, const std::filesystem::path& out);

}  // namespace sextant
