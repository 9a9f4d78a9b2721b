#pragma once
// Experiment YAML, runs and report pieces for the experiments tests (temporary folders:
// sextant_test/temp_dir.hpp).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sextant/experiments/runner.hpp"
#include "sextant_test/temp_dir.hpp"

namespace sextant::test {

/// The repository's experiments/ folder: the configs whose quick profiles the tests run.
inline std::filesystem::path experiments_dir() {
  return std::filesystem::path(SEXTANT_SOURCE_DIR) / "experiments";
}

/// Runner options that write under `results`: two jobs, no progress bar, the quick profile when
/// `quick`.
inline RunnerOptions runner_options(const std::filesystem::path& results, bool quick = false) {
  RunnerOptions o;
  o.results_root = results;
  o.jobs = 2;
  o.quick = quick;
  o.progress = false;
  return o;
}

/// Runs `config` into `results`: its quick profile unless `quick` is false.
inline RunnerSummary run_quick(const std::filesystem::path& config, const std::filesystem::path& results,
                               bool quick = true) {
  return run_experiment(config, runner_options(results, quick));
}

/// Data rows of the Markdown tables in `md`: the lines starting with "|" after a separator line.
inline std::size_t markdown_rows(const std::string& md) {
  std::size_t rows = 0;
  bool body = false;
  std::istringstream in(md);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| :", 0) == 0 || line.rfind("|---", 0) == 0)
      body = true;
    else if (body && line.rfind("|", 0) == 0)
      ++rows;
    else
      body = false;
  }
  return rows;
}

/// A selftest experiment with `points` sweep values × 2 methods × `reps` repetitions.
inline std::string selftest_yaml(const std::string& name, int points, int reps, int sleep_ms) {
  return "name: " + name + "\nkind: selftest\nrepetitions: " + std::to_string(reps) +
         "\nseed: 7\nmethods:\n  - name: a\n  - name: b\nsweep:\n  x: {from: 1, to: " +
         std::to_string(points) + "}\nparams:\n  sleep_ms: " + std::to_string(sleep_ms) + "\n";
}

/// The HTML of the report section `<section id="id">` … `</section>` ("" when absent).
inline std::string report_section(const std::string& index_html, const std::string& id) {
  const std::size_t at = index_html.find("<section id=\"" + id + "\">");
  if (at == std::string::npos) return "";
  return index_html.substr(at, index_html.find("</section>", at) - at);
}

/// The targets of the 3D-view links (<p class="sx-view"><a href="…">) in a piece of the report.
inline std::vector<std::string> view_links(const std::string& html) {
  std::vector<std::string> out;
  const std::string open = "<p class=\"sx-view\"><a href=\"";
  for (std::size_t at = html.find(open); at != std::string::npos; at = html.find(open, at + 1)) {
    const std::size_t from = at + open.size();
    out.push_back(html.substr(from, html.find('"', from) - from));
  }
  return out;
}

}  // namespace sextant::test
