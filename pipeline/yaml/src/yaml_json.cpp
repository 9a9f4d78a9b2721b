// YAML nodes as JSON (yaml_json.hpp).
#include "sextant/pipeline/yaml_json.hpp"

#include <cmath>

namespace sextant {
namespace {

/// A plain YAML scalar that is a JSON number or boolean, as that value; null otherwise. A quoted
/// scalar (tag "!") stays a string, and so does a number JSON cannot hold (1e999, .inf, 0x1F).
Json typed_scalar(const YAML::Node& node) {
  if (node.Tag() == "!") return nullptr;
  const Json v = Json::parse(node.Scalar(), nullptr, false);
  if (v.is_boolean() || v.is_number_integer()) return v;
  if (v.is_number_float() && std::isfinite(v.get<double>())) return v;
  return nullptr;
}

/// The YAML node as JSON: `canonical` keeps every scalar a string and sorts the maps by key.
template <class J>
J node_json(const YAML::Node& node, bool canonical) {
  switch (node.Type()) {
    case YAML::NodeType::Scalar: {
      if (!canonical) {
        Json typed = typed_scalar(node);
        if (!typed.is_null()) return J(typed);
      }
      return J(node.Scalar());
    }
    case YAML::NodeType::Sequence: {
      J out = J::array();
      for (const auto& item : node) out.push_back(node_json<J>(item, canonical));
      return out;
    }
    case YAML::NodeType::Map: {
      J out = J::object();  // nlohmann::json sorts its keys, ordered_json keeps the file's order
      for (const auto& entry : node)
        out[entry.first.as<std::string>()] = node_json<J>(entry.second, canonical);
      return out;
    }
    default: return nullptr;
  }
}

}  // namespace

std::string canonical_json(const YAML::Node& node) {
  return json_compact(node_json<nlohmann::json>(node, true));
}

Json yaml_to_json(const YAML::Node& node) {
  return node_json<Json>(node, false);
}

std::string to_json(const YAML::Node& node) {
  return json_compact(yaml_to_json(node));
}

}  // namespace sextant
