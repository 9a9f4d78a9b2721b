#pragma once
// What every family's layout table (<family>/layouts/layouts.cpp) needs: a line by its name (the
// value of `report:`, `study:` or `model:`), and the names for the error message ("a, b or c").
#include <string>
#include <vector>

#include "sextant/core/settings_reader.hpp"
#include "sextant/experiments/experiment_config.hpp"

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

/// The line named by the required key `key` of config.params; InputError at that key's line when
/// the name is not in the table: "key 'study': 'x' is not merging or extraction".
template <class Layout>
const Layout& layout_named_by(const std::vector<Layout>& table, const ExperimentConfig& config,
                              const char* key) {
  SettingsReader in(config.params, config.file);
  std::string name;
  in.require(key, name);
  if (const Layout* l = find_layout(table, name)) return *l;
  in.fail(key, "key '" + std::string(key) + "': '" + name + "' is not " + layout_names(table));
}

}  // namespace sextant
