#pragma once
// Small JSON helpers for result rows and provenance: escaping, number formatting that
// round-trips, and the canonical form of a YAML node used to hash a run's resolved config.
#include <cstdint>
#include <string>

#include <yaml-cpp/yaml.h>

namespace sextant {

/// `text` as a JSON string literal, quotes included.
std::string json_string(const std::string& text);
/// A double as a JSON number that reads back to the same value; NaN and ±Inf become null.
std::string json_number(double value);
/// A YAML node as canonical JSON: maps sorted by key, no whitespace, every scalar a string.
/// Two nodes with the same content give the same text whatever their layout in the file.
std::string canonical_json(const YAML::Node& node);
/// A YAML node as ordinary JSON (numbers and booleans unquoted when the scalar is one).
std::string to_json(const YAML::Node& node);
/// FNV-1a 64-bit hash of `text` (stable across platforms and runs).
std::uint64_t stable_hash(const std::string& text);
/// 16 lowercase hex digits.
std::string hex64(std::uint64_t value);

}  // namespace sextant
