#pragma once
// YAML nodes as JSON (Sextant::pipeline_yaml): a run's resolved config in provenance.json and
// runs.jsonl, and its canonical form, whose hash keys a run.
#include <string>

#include <yaml-cpp/yaml.h>

#include "sextant/pipeline/json.hpp"

namespace sextant {

/// A YAML node as canonical JSON: maps sorted by key, no whitespace, every scalar a string.
/// Two nodes with the same content give the same text whatever their layout in the file.
std::string canonical_json(const YAML::Node& node);
/// A YAML node as ordinary JSON (numbers and booleans unquoted when the scalar is one).
Json yaml_to_json(const YAML::Node& node);
/// yaml_to_json(node), compact: no whitespace.
std::string to_json(const YAML::Node& node);

}  // namespace sextant
