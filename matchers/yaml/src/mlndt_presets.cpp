// The wide basin switched on in a settings map (matchers/yaml.hpp).
#include "sextant/matchers/yaml.hpp"

#include "sextant/matchers/matcher_traits.hpp"

namespace sextant {

std::optional<YAML::Node> with_wide_basin(const std::string& matcher, const YAML::Node& settings) {
  if (!matcher_traits(matcher).has_wide_basin) return std::nullopt;
  YAML::Node wide = settings.IsMap() ? YAML::Clone(settings) : YAML::Node(YAML::NodeType::Map);
  if (!wide["wide_basin"].IsDefined()) wide["wide_basin"] = YAML::Node(YAML::NodeType::Map);
  return wide;
}

}  // namespace sextant
