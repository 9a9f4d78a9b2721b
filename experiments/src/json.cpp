#include "sextant/experiments/json.hpp"

#include <cmath>
#include <cstdio>

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

/// Compact text; bytes that are not UTF-8 become U+FFFD instead of throwing.
template <class J>
std::string dump(const J& value) {
  return value.dump(-1, ' ', false, J::error_handler_t::replace);
}

void append_line(const Json& value, std::string& out) {
  if (value.is_object()) {
    out += '{';
    bool first = true;
    for (const auto& [key, item] : value.items()) {
      out += first ? "" : ", ";
      out += dump(Json(key)) + ": ";
      append_line(item, out);
      first = false;
    }
    out += '}';
  } else if (value.is_array()) {
    out += '[';
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (i) out += ", ";
      append_line(value[i], out);
    }
    out += ']';
  } else {
    out += dump(value);
  }
}

}  // namespace

std::string json_string(const std::string& text) {
  return dump(Json(text));
}

std::string json_number(double value) {
  return dump(json_value(value));
}

Json json_value(double value) {
  return std::isfinite(value) ? Json(value) : Json(nullptr);
}

std::string json_line(const Json& value) {
  std::string out;
  append_line(value, out);
  return out;
}

std::string json_lines(const Json& object, const std::set<std::string>& compact) {
  std::string out = "{\n";
  bool first = true;
  for (const auto& [key, item] : object.items()) {
    out += first ? "  " : ",\n  ";
    out += dump(Json(key)) + ": " + (compact.count(key) ? dump(item) : json_line(item));
    first = false;
  }
  return out + "\n}\n";
}

std::string canonical_json(const YAML::Node& node) {
  return dump(node_json<nlohmann::json>(node, true));
}

Json yaml_to_json(const YAML::Node& node) {
  return node_json<Json>(node, false);
}

std::string to_json(const YAML::Node& node) {
  return dump(yaml_to_json(node));
}

std::uint64_t stable_hash(const std::string& text) {
  std::uint64_t h = 14695981039346656037ULL;  // FNV-1a 64
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
  return h;
}

std::string hex64(std::uint64_t value) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(value));
  return buf;
}

}  // namespace sextant
