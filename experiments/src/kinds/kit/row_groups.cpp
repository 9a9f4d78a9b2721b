#include "kit/row_groups.hpp"

namespace sextant {

std::vector<double> MethodRows::values(const std::string& key) const {
  return row_values(rows, key);
}

std::string point_key(const std::map<std::string, std::string>& point, int repetition) {
  std::string key;
  for (const auto& [axis, label] : point) key += axis + "=" + label + ";";
  return key + "rep=" + std::to_string(repetition);
}

std::vector<MethodRows> group_by_method(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                                        const std::vector<const RunRow*>& rows) {
  std::vector<MethodRows> out(config.methods.size());
  for (std::size_t m = 0; m < out.size(); ++m) out[m].name = config.methods[m].name;
  for (std::size_t i = 0; i < runs.size() && i < rows.size(); ++i) {
    if (!rows[i] || !rows[i]->ok) continue;
    MethodRows& m = out.at(runs[i].method_index);
    m.rows.push_back(rows[i]);
    m.by_point[point_key(runs[i].point, runs[i].repetition)] = rows[i];
  }
  return out;
}

const MethodRows* find_method(const std::vector<MethodRows>& methods, const std::string& name) {
  for (const auto& m : methods) {
    if (m.name == name && !m.rows.empty()) return &m;
  }
  return nullptr;
}

PairedRows pair_up(const MethodRows& a, const MethodRows& b) {
  PairedRows p;
  for (const auto& [key, row] : a.by_point) {
    const auto it = b.by_point.find(key);
    if (it == b.by_point.end()) continue;
    p.a.push_back(row);
    p.b.push_back(it->second);
  }
  return p;
}

PairedRows pair_up_in_order(const MethodRows& a, const MethodRows& b) {
  PairedRows p;
  for (const RunRow* row : a.rows) {
    const auto it = b.by_point.find(point_key(row->point, row->repetition));
    if (it == b.by_point.end()) continue;
    p.a.push_back(row);
    p.b.push_back(it->second);
  }
  return p;
}

std::vector<double> row_values(const std::vector<const RunRow*>& rows, const std::string& key) {
  std::vector<double> v;
  v.reserve(rows.size());
  for (const RunRow* r : rows) v.push_back(r->value(key));
  return v;
}

}  // namespace sextant
