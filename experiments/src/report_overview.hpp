#pragma once
// The report's front page: one row per experiment (title, where in the thesis, claims held / total,
// a one-line outcome, a link to its section), the thesis' nineteen apart from later extensions.
#include <cstddef>
#include <string>
#include <vector>

#include "sextant/eval/html_report.hpp"

namespace sextant {

struct OverviewEntry {
  std::string id;  ///< section id and result folder, e.g. "e02_accuracy_100_scans"
  std::string title;
  std::string thesis;   ///< e.g. "§5.1.1.2 A, tables 5.1-5.4, figs 5.7-5.10"
  std::string profile;  ///< "quick", "full" or "" when unknown
  std::size_t runs_found = 0, runs_expected = 0;
  std::size_t runs_failed = 0;  ///< expected runs with only a failed row
  std::vector<Claim> claims;    ///< thesis claims and sanity checks
  std::string failure;          ///< non-empty when the experiment's report failed
  bool real_data = false;       ///< its scans are a folder of real data, not the synthetic campus
};

/// The experiment number of a folder name "eNN_…" (0 when the name has no such prefix).
int experiment_number(const std::string& id);
/// "3 of 4 claims hold; 1 inconclusive: <statement>" — counts thesis claims only.
std::string one_line_outcome(const OverviewEntry& entry);
/// One sentence for the top of the front page: the thesis' claims (E1–E19) by verdict, on the campus
/// apart from on real data, then the extensions' claims and the sanity checks (which test the
/// experiments, not the thesis).
std::string headline_text(const std::vector<OverviewEntry>& entries);
/// The headline, then two HTML tables (the thesis' experiments E1–E19, then extensions E20+ and others).
std::string overview_html(const std::vector<OverviewEntry>& entries);
/// The same as Markdown (report/overview.md).
std::string overview_markdown(const std::vector<OverviewEntry>& entries);

}  // namespace sextant
