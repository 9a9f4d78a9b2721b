#include "sextant/experiments/json.hpp"

#include <cmath>
#include <cstdio>
#include <map>

namespace sextant {
namespace {

bool looks_like_json_number(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !std::isfinite(v)) return false;
  // JSON forbids leading '+', leading zeros and a bare '.', which strtod accepts.
  const std::size_t digits = s[0] == '-' ? 1 : 0;
  if (s[0] == '+' || s.size() <= digits) return false;
  if (s[digits] == '.' ||
      (s[digits] == '0' && s.size() > digits + 1 && std::isdigit(static_cast<unsigned char>(s[digits + 1]))))
    return false;
  return s.find_first_of("xXnN") == std::string::npos;
}

std::string scalar_json(const YAML::Node& node, bool typed) {
  const std::string& s = node.Scalar();
  if (typed && node.Tag() != "!") {  // a quoted scalar has tag "!" and stays a string
    if (looks_like_json_number(s) || s == "true" || s == "false") return s;
  }
  return json_string(s);
}

std::string node_json(const YAML::Node& node, bool canonical) {
  switch (node.Type()) {
    case YAML::NodeType::Scalar: return scalar_json(node, !canonical);
    case YAML::NodeType::Sequence: {
      std::string out = "[";
      for (std::size_t i = 0; i < node.size(); ++i) {
        if (i) out += ",";
        out += node_json(node[i], canonical);
      }
      return out + "]";
    }
    case YAML::NodeType::Map: {
      std::map<std::string, std::string> sorted;
      std::string out = "{";
      bool first = true;
      for (const auto& entry : node) {
        const std::string key = entry.first.as<std::string>();
        const std::string value = node_json(entry.second, canonical);
        if (canonical) {
          sorted[key] = value;
        } else {
          out += (first ? "" : ",") + json_string(key) + ":" + value;
          first = false;
        }
      }
      if (!canonical) return out + "}";
      for (const auto& [key, value] : sorted) {
        out += (first ? "" : ",") + json_string(key) + ":" + value;
        first = false;
      }
      return out + "}";
    }
    default: return "null";
  }
}

}  // namespace

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string json_number(double value) {
  if (!std::isfinite(value)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  // Prefer the shortest representation that reads back exactly.
  for (int precision = 6; precision < 17; ++precision) {
    char shorter[32];
    std::snprintf(shorter, sizeof shorter, "%.*g", precision, value);
    if (std::strtod(shorter, nullptr) == value) return shorter;
  }
  return buf;
}

std::string canonical_json(const YAML::Node& node) {
  return node_json(node, true);
}
std::string to_json(const YAML::Node& node) {
  return node_json(node, false);
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
