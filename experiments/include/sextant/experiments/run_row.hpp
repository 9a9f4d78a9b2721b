#pragma once
// One result row per run, stored as a JSON line in results/<experiment>/runs.jsonl (appended
// durably as each run finishes) and mirrored into runs.csv.
#include <cstddef>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "sextant/experiments/run_plan.hpp"

namespace sextant {

struct RunRow {
  std::string key;
  std::string experiment;
  std::string method;
  std::map<std::string, std::string> point;
  int repetition = 0;
  std::uint64_t seed = 0;
  bool ok = true;  ///< false when the run threw (the message is in `error`); such runs are retried
  std::string error;
  double seconds = 0.0;                               ///< wall time of the run
  std::map<std::string, double> values;               ///< scalar metrics (NaN allowed)
  std::map<std::string, std::vector<double>> series;  ///< curves (per iteration, per scan, ...)

  /// NaN when absent.
  double value(const std::string& name) const;
};

/// The series `name` of the row; empty when absent.
const std::vector<double>& series_or_empty(const RunRow& row, const std::string& name);

/// A row with the run's identity filled in.
RunRow row_for(const RunSpec& run, const std::string& experiment);

std::string to_json_line(const RunRow& row);
/// Parses one line; returns false (and leaves `row` unspecified) for a truncated or malformed line.
bool parse_json_line(const std::string& line, RunRow& row);

struct RowFile {
  std::vector<RunRow> rows;            ///< in file order; the last row wins for a repeated key
  std::size_t bad_lines = 0;           ///< truncated or malformed lines skipped (a killed writer)
  std::vector<long> bad_line_numbers;  ///< their 1-based line numbers, to name them
};

/// "results/e01/runs.jsonl:7: unreadable line skipped (…)" for each bad line of `file`.
std::vector<std::string> bad_line_messages(const std::filesystem::path& jsonl, const RowFile& file);

/// Reads runs.jsonl (missing file = no rows); keeps only the last row of each key.
RowFile read_rows(const std::filesystem::path& jsonl);
/// The rows in the order of `runs` (the expansion order: the same whatever the shards or threads
/// that produced them), then the rows of keys not in `runs` (older configs, the other profile) in
/// their given order. One row per key.
std::vector<RunRow> in_expansion_order(const std::vector<RunRow>& rows, const std::vector<RunSpec>& runs);

/// Writes rows as CSV atomically: key, method, point.<axis>..., repetition, seed, ok, seconds, <values>...
void write_rows_csv(const std::filesystem::path& csv, const std::vector<RunRow>& rows);

}  // namespace sextant
