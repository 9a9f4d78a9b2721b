#pragma once
// JSON for result rows, provenance and metrics, by nlohmann::json (Debian's nlohmann-json3-dev):
// escaping and number formatting that round-trips (the shortest text that reads back to the same
// double) come from it; what is ours is the layout of our files and the canonical form of a YAML
// node used to hash a run's resolved config.
//
//   Json row = {{"key", key}, {"values", {{"rmse", 0.25}}}};
//   out << json_line(row);             // {"key": "…", "values": {"rmse": 0.25}}
//   const Json back = Json::parse(line);
#include <cstdint>
#include <set>
#include <string>

#include <yaml-cpp/yaml.h>
#include <nlohmann/json.hpp>

namespace sextant {

/// A JSON value whose objects keep their keys in insertion order (the order our files list them).
using Json = nlohmann::ordered_json;

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
/// A YAML node as canonical JSON: maps sorted by key, no whitespace, every scalar a string.
/// Two nodes with the same content give the same text whatever their layout in the file.
std::string canonical_json(const YAML::Node& node);
/// A YAML node as ordinary JSON (numbers and booleans unquoted when the scalar is one).
Json yaml_to_json(const YAML::Node& node);
/// yaml_to_json(node), compact: no whitespace.
std::string to_json(const YAML::Node& node);
/// FNV-1a 64-bit hash of `text` (stable across platforms and runs).
std::uint64_t stable_hash(const std::string& text);
/// 16 lowercase hex digits.
std::string hex64(std::uint64_t value);

}  // namespace sextant
