#include "sextant/pipeline/json.hpp"

#include <cmath>
#include <cstdio>

namespace sextant {
namespace {

void append_line(const Json& value, std::string& out) {
  if (value.is_object()) {
    out += '{';
    bool first = true;
    for (const auto& [key, item] : value.items()) {
      out += first ? "" : ", ";
      out += json_compact(Json(key)) + ": ";
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
    out += json_compact(value);
  }
}

}  // namespace

std::string json_string(const std::string& text) {
  return json_compact(Json(text));
}

std::string json_number(double value) {
  return json_compact(json_value(value));
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
    out += json_compact(Json(key)) + ": " + (compact.count(key) ? json_compact(item) : json_line(item));
    first = false;
  }
  return out + "\n}\n";
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
