#pragma once
// Reading back what `sextant odometry` writes, for its end-to-end tests: a number of metrics.json or
// provenance.json, and steps.csv as rows of named fields (a file's text: read_text of temp_dir.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace sextant::test {

namespace fs = std::filesystem;

/// The number after "key": (first occurrence after `after`); NaN when absent or null.
inline double json_number(const std::string& json, const std::string& key, const std::string& after = "") {
  const auto from = after.empty() ? 0 : json.find("\"" + after + "\"");
  const auto at = json.find("\"" + key + "\": ", from == std::string::npos ? 0 : from);
  if (at == std::string::npos) return NAN;
  const char* start = json.c_str() + at + key.size() + 4;
  char* end = nullptr;
  const double v = std::strtod(start, &end);
  return end == start ? NAN : v;
}

/// steps.csv as rows of named fields (the header's names).
inline std::vector<std::map<std::string, std::string>> read_steps_csv(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> names;
  std::vector<std::map<std::string, std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    if (names.empty()) {
      names = fields;
      continue;
    }
    EXPECT_EQ(fields.size(), names.size()) << line;
    auto& row = rows.emplace_back();
    for (std::size_t i = 0; i < names.size() && i < fields.size(); ++i) row[names[i]] = fields[i];
  }
  return rows;
}

}  // namespace sextant::test
