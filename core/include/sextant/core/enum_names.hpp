#pragma once
// One rule for every enum a user names in text (a flag, a YAML value, a keyword argument): its names in
// one table beside the enum, and the same functions for each, made from the table:
//
//   inline constexpr EnumNames<Platform, 3> kPlatformNames{
//       "platform", {{{Platform::automatic, "auto"}, {Platform::car, "car"}, {Platform::handheld,
//       "handheld"}}}};
//   bool from_string(const std::string& text, Platform* out) { return from_name(kPlatformNames, text, out); }
//   std::string to_string(Platform p) { return name_of(kPlatformNames, p); }
//   const Platform p = parse_enum(kPlatformNames, text, "--platform");  // or InputError naming --platform
#include <array>
#include <cstddef>
#include <string>
#include <utility>

#include "sextant/core/error.hpp"

namespace sextant {

/// An enum's names: what one value is called in a message ("platform", "guess mode"), and each value's
/// name, in the order a message lists them.
template <class E, std::size_t N>
struct EnumNames {
  const char* noun;
  std::array<std::pair<E, const char*>, N> names;
};

/// The value named `text` into *out; false (and *out unchanged) when no value has that name.
template <class E, std::size_t N>
bool from_name(const EnumNames<E, N>& table, const std::string& text, E* out) {
  for (const auto& [value, name] : table.names)
    if (text == name) {
      *out = value;
      return true;
    }
  return false;
}

/// The name of `value` ("?" for a value the table lacks).
template <class E, std::size_t N>
std::string name_of(const EnumNames<E, N>& table, E value) {
  for (const auto& [v, name] : table.names)
    if (v == value) return name;
  return "?";
}

/// "a, b, c": the names in the table's order.
template <class E, std::size_t N>
std::string names_list(const EnumNames<E, N>& table) {
  std::string out;
  for (const auto& entry : table.names) out += (out.empty() ? "" : ", ") + std::string(entry.second);
  return out;
}

/// The value named `text`, else InputError(what): "unknown <noun> '<text>' (known: a, b, c)".
template <class E, std::size_t N>
E parse_enum(const EnumNames<E, N>& table, const std::string& text, const std::string& what) {
  E value{};
  if (!from_name(table, text, &value))
    throw InputError(
        what, "",
        "unknown " + std::string(table.noun) + " '" + text + "' (known: " + names_list(table) + ")");
  return value;
}

}  // namespace sextant
