#pragma once
// What every family's layout table (<family>/layouts/layouts.cpp) needs: a line by its `report:`
// name, and the names for the error message ("a, b or c").
#include <string>
#include <vector>

namespace sextant {

/// The line named `name`; nullptr when there is none.
template <class Layout>
const Layout* find_layout(const std::vector<Layout>& table, const std::string& name) {
  for (const Layout& l : table)
    if (name == l.name) return &l;
  return nullptr;
}

/// "a, b or c".
template <class Layout>
std::string layout_names(const std::vector<Layout>& table) {
  std::string out;
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (i > 0) out += i + 1 == table.size() ? " or " : ", ";
    out += table[i].name;
  }
  return out;
}

}  // namespace sextant
