#pragma once
// Reading the thesis' values from an experiment's `reference:` block, where any of them may be
// absent (the report then shows a missing cell rather than failing).
#include <optional>
#include <string>

#include <yaml-cpp/yaml.h>

namespace sextant {

/// `node[key]` when `node` is a map holding `key`, else a null node. (yaml-cpp's const operator[]
/// returns an invalid node for a missing key, and asking that node anything but IsDefined() throws.)
YAML::Node child_or_null(const YAML::Node& node, const std::string& key);
/// A number under `key` of a map node, or nullopt.
std::optional<double> reference_number(const YAML::Node& node, const std::string& key);

}  // namespace sextant
