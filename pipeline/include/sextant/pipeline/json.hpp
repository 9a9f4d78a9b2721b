#pragma once
// JSON for result rows, provenance and metrics, by nlohmann::json (Debian's nlohmann-json3-dev):
// escaping and number formatting that round-trips (the shortest text that reads back to the same
// double) come from it; what is ours is the layout of our files (YAML nodes as JSON: yaml_json.hpp,
// Sextant::pipeline_yaml).
//
//   Json row = {{"key", key}, {"values", {{"rmse", 0.25}}}};
//   out << json_line(row);             // {"key": "…", "values": {"rmse": 0.25}}
//   const Json back = Json::parse(line);
#include <cstdint>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

namespace sextant {

/// A JSON value whose objects keep their keys in insertion order (the order our files list them).
using Json = nlohmann::ordered_json;

/// `value` as compact text without whitespace; bytes that are not UTF-8 become U+FFFD instead of
/// throwing.
template <class J>
std::string json_compact(const J& value) {
  return value.dump(-1, ' ', false, J::error_handler_t::replace);
}
/// `text` as a JSON string literal, quotes included.
std::string json_string(const std::string& text);
/// A double as a JSON number that reads back to the same value; NaN and ±Inf become null.
std::string json_number(double value);
/// A double as a JSON value: the number, or null when it is NaN or ±Inf.
Json json_value(double value);
/// `value` on one line with ", " between items and ": " after keys, the layout of runs.jsonl,
/// metrics.json and the CLI's --json (scripts read them line by line): {"a": 1, "b": [2, 3]}.
std::string json_line(const Json& value);
/// A JSON object with each top-level entry on its own line, indented by two spaces, each value on
/// one line (json_line, or compact without whitespace for the keys in `compact`, the configs);
/// ends with a newline. The layout of provenance.json.
std::string json_lines(const Json& object, const std::set<std::string>& compact = {});
/// FNV-1a 64-bit hash of `text` (stable across platforms and runs).
std::uint64_t stable_hash(const std::string& text);
/// 16 lowercase hex digits.
std::string hex64(std::uint64_t value);

}  // namespace sextant
