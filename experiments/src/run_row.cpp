#include "sextant/experiments/run_row.hpp"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "sextant/core/atomic_file.hpp"
#include "sextant/core/units.hpp"
#include "sextant/pipeline/json.hpp"

namespace sextant {
namespace {

/// A number of a row: null (NaN or ±Inf when written) reads back as NaN.
double number_of(const Json& value) {
  return value.is_number() ? value.get<double>() : kNaN;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

double RunRow::value(const std::string& name) const {
  const auto it = values.find(name);
  return it == values.end() ? kNaN : it->second;
}

const std::vector<double>& series_or_empty(const RunRow& row, const std::string& name) {
  static const std::vector<double> empty;
  const auto it = row.series.find(name);
  return it == row.series.end() ? empty : it->second;
}

RunRow row_for(const RunSpec& run, const std::string& experiment) {
  RunRow row;
  row.key = run.key;
  row.experiment = experiment;
  row.method = run.method;
  row.point = run.point;
  row.repetition = run.repetition;
  row.seed = run.seed;
  return row;
}

std::string to_json_line(const RunRow& row) {
  Json values = Json::object(), series = Json::object();
  for (const auto& [name, v] : row.values) values[name] = json_value(v);
  for (const auto& [name, v] : row.series) {
    Json& s = series[name] = Json::array();
    for (double x : v) s.push_back(json_value(x));
  }
  return json_line(Json{{"key", row.key},
                        {"experiment", row.experiment},
                        {"method", row.method},
                        {"point", row.point},
                        {"repetition", row.repetition},
                        {"seed", std::to_string(row.seed)},
                        {"ok", row.ok},
                        {"error", row.error},
                        {"seconds", json_value(row.seconds)},
                        {"values", values},
                        {"series", series}});
}

bool parse_json_line(const std::string& line, RunRow& row) {
  if (line.empty() || line.front() != '{' || line.back() != '}') return false;
  try {
    const Json n = Json::parse(line);
    if (!n.is_object() || !n.contains("key") || !n["key"].is_string()) return false;
    row = RunRow{};
    row.key = n["key"].get<std::string>();
    row.experiment = n.value("experiment", "");
    row.method = n.value("method", "");
    if (n.contains("point"))
      for (const auto& [name, v] : n["point"].items()) row.point[name] = v.get<std::string>();
    row.repetition = n.value("repetition", 0);
    row.seed = std::stoull(n.value("seed", "0"));
    row.ok = n.value("ok", false);
    row.error = n.value("error", "");
    row.seconds = number_of(n.value("seconds", Json()));
    if (n.contains("values"))
      for (const auto& [name, v] : n["values"].items()) row.values[name] = number_of(v);
    if (n.contains("series")) {
      for (const auto& [name, list] : n["series"].items()) {
        auto& s = row.series[name];
        for (const auto& v : list) s.push_back(number_of(v));
      }
    }
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

RowFile read_rows(const std::filesystem::path& jsonl) {
  RowFile file;
  std::ifstream in(jsonl, std::ios::binary);
  if (!in) return file;
  std::unordered_map<std::string, std::size_t> position;
  std::string line;
  long number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    RunRow row;
    if (!parse_json_line(line, row)) {
      ++file.bad_lines;
      file.bad_line_numbers.push_back(number);
      continue;
    }
    const auto it = position.find(row.key);
    if (it == position.end()) {
      position[row.key] = file.rows.size();
      file.rows.push_back(std::move(row));
    } else {
      file.rows[it->second] = std::move(row);
    }
  }
  return file;
}

std::vector<std::string> bad_line_messages(const std::filesystem::path& jsonl, const RowFile& file) {
  std::vector<std::string> out;
  for (long n : file.bad_line_numbers) {
    out.push_back(jsonl.string() + ":" + std::to_string(n) +
                  ": unreadable line skipped (truncated or corrupted); its run, if any, counts as missing");
  }
  return out;
}

std::vector<RunRow> in_expansion_order(const std::vector<RunRow>& rows, const std::vector<RunSpec>& runs) {
  std::unordered_map<std::string, const RunRow*> by_key;
  for (const auto& r : rows) by_key[r.key] = &r;
  std::vector<RunRow> out;
  std::unordered_set<std::string> placed;
  for (const auto& run : runs) {
    const auto it = by_key.find(run.key);
    if (it != by_key.end() && placed.insert(run.key).second) out.push_back(*it->second);
  }
  for (const auto& r : rows) {
    if (placed.insert(r.key).second) out.push_back(r);
  }
  return out;
}

void write_rows_csv(const std::filesystem::path& csv, const std::vector<RunRow>& rows) {
  std::set<std::string> axes, values;
  for (const auto& row : rows) {
    for (const auto& [k, v] : row.point) axes.insert(k);
    for (const auto& [k, v] : row.values) values.insert(k);
  }
  std::ostringstream out;
  out << "key,method";
  for (const auto& a : axes) out << "," << csv_field("point." + a);
  out << ",repetition,seed,ok,seconds";
  for (const auto& v : values) out << "," << csv_field(v);
  out << "\n";
  for (const auto& row : rows) {
    out << row.key << "," << csv_field(row.method);
    for (const auto& a : axes) {
      const auto it = row.point.find(a);
      out << "," << (it == row.point.end() ? "" : csv_field(it->second));
    }
    out << "," << row.repetition << "," << row.seed << "," << (row.ok ? "true" : "false") << ","
        << json_number(row.seconds);
    for (const auto& v : values) {
      const double x = row.value(v);
      out << "," << (std::isfinite(x) ? json_number(x) : "");
    }
    out << "\n";
  }
  write_file_atomically(csv, out.str());
}

}  // namespace sextant
