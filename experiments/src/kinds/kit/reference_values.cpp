#include "kit/reference_values.hpp"

namespace sextant {

YAML::Node child_or_null(const YAML::Node& node, const std::string& key) {
  if (!node.IsDefined() || !node.IsMap()) return YAML::Node();
  const YAML::Node child = node[key];
  return child.IsDefined() ? child : YAML::Node();
}

std::optional<double> reference_number(const YAML::Node& node, const std::string& key) {
  if (!node.IsMap() || !node[key].IsDefined() || node[key].IsNull()) return std::nullopt;
  return node[key].as<double>();
}

}  // namespace sextant
