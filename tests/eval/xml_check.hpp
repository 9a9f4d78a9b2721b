#pragma once
// Test helper: a minimal XML well-formedness check (tags nest, attributes quoted and unique,
// entities valid, one root) that also counts elements by name.
#include <cctype>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace sextant::testing {

/// How often `what` occurs in `s` (overlapping occurrences too).
inline int occurrences(const std::string& s, const std::string& what) {
  int n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

struct XmlCheck {
  bool ok = true;
  std::string error;
  std::map<std::string, int> elements;  ///< element name → count
};

inline bool valid_entity(const std::string& s, std::size_t amp, std::size_t* end) {
  const std::size_t semi = s.find(';', amp);
  if (semi == std::string::npos || semi - amp > 10) return false;
  const std::string name = s.substr(amp + 1, semi - amp - 1);
  *end = semi + 1;
  static const std::set<std::string> named{"amp", "lt", "gt", "quot", "apos"};
  if (named.count(name)) return true;
  if (name.size() > 1 && name[0] == '#') {
    const bool hex = name[1] == 'x';
    if (name.size() == (hex ? 2u : 1u)) return false;
    for (std::size_t k = hex ? 2 : 1; k < name.size(); ++k)
      if (!(hex ? std::isxdigit(static_cast<unsigned char>(name[k]))
                : std::isdigit(static_cast<unsigned char>(name[k]))))
        return false;
    return true;
  }
  return false;
}

inline XmlCheck check_xml(const std::string& s) {
  XmlCheck r;
  auto fail = [&r](const std::string& why, std::size_t at) {
    r.ok = false;
    r.error = why + " at offset " + std::to_string(at);
    return r;
  };
  auto is_name_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '-' || c == '.';
  };
  std::vector<std::string> stack;
  int roots = 0;
  std::size_t i = 0;
  while (i < s.size()) {
    if (s.compare(i, 2, "<?") == 0) {
      const std::size_t e = s.find("?>", i);
      if (e == std::string::npos) return fail("unterminated <?", i);
      i = e + 2;
    } else if (s.compare(i, 4, "<!--") == 0) {
      const std::size_t e = s.find("-->", i);
      if (e == std::string::npos) return fail("unterminated comment", i);
      i = e + 3;
    } else if (s.compare(i, 2, "</") == 0) {
      std::size_t j = i + 2;
      while (j < s.size() && is_name_char(s[j])) ++j;
      const std::string name = s.substr(i + 2, j - i - 2);
      while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
      if (j >= s.size() || s[j] != '>') return fail("bad end tag", i);
      if (stack.empty() || stack.back() != name) return fail("mismatched </" + name + ">", i);
      stack.pop_back();
      i = j + 1;
    } else if (s[i] == '<') {
      std::size_t j = i + 1;
      while (j < s.size() && is_name_char(s[j])) ++j;
      const std::string name = s.substr(i + 1, j - i - 1);
      if (name.empty()) return fail("empty tag name", i);
      if (stack.empty() && ++roots > 1) return fail("second root element", i);
      ++r.elements[name];
      std::set<std::string> attributes;
      while (true) {
        while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
        if (j >= s.size()) return fail("unterminated tag", i);
        if (s.compare(j, 2, "/>") == 0) {
          j += 2;
          break;
        }
        if (s[j] == '>') {
          stack.push_back(name);
          ++j;
          break;
        }
        std::size_t k = j;
        while (k < s.size() && is_name_char(s[k])) ++k;
        const std::string attribute = s.substr(j, k - j);
        if (attribute.empty() || k >= s.size() || s[k] != '=')
          return fail("bad attribute in <" + name + ">", j);
        if (!attributes.insert(attribute).second) return fail("duplicate attribute " + attribute, j);
        const char quote = s[k + 1];
        if (quote != '"' && quote != '\'') return fail("unquoted attribute " + attribute, k);
        const std::size_t close = s.find(quote, k + 2);
        if (close == std::string::npos) return fail("unterminated attribute", k);
        for (std::size_t a = k + 2; a < close; ++a) {
          if (s[a] == '<') return fail("'<' in attribute", a);
          std::size_t end = 0;
          if (s[a] == '&' && !valid_entity(s, a, &end)) return fail("bad entity in attribute", a);
        }
        j = close + 1;
      }
      i = j;
    } else {
      if (s[i] == '&') {
        std::size_t end = 0;
        if (!valid_entity(s, i, &end)) return fail("bad entity", i);
        i = end;
        continue;
      }
      if (stack.empty() && !std::isspace(static_cast<unsigned char>(s[i])))
        return fail("text outside the root", i);
      ++i;
    }
  }
  if (!stack.empty()) return fail("unclosed <" + stack.back() + ">", s.size());
  if (roots != 1) return fail("no root element", 0);
  return r;
}

}  // namespace sextant::testing
