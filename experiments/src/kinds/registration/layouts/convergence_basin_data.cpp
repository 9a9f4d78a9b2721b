// E1: the report settings and the runs grouped per method, scene and offset
// (registration/layouts/convergence_basin.hpp).
#include <algorithm>
#include <cmath>
#include <map>

#include "registration/layouts/convergence_basin.hpp"
#include "registration/row_keys.hpp"
#include "registration/scenes.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"

namespace sextant {
namespace {

void read_pair(SettingsReader& in, const char* key, std::array<double, 2>& band) {
  std::vector<double> v;
  if (!in.read(key, v)) return;
  if (v.size() != 2 || !(v[0] <= v[1])) in.fail(key, "key '" + std::string(key) + "': expected [low, high]");
  band = {v[0], v[1]};
}

void read_thesis(const YAML::Node& node, const std::string& file, double& translation, double& yaw,
                 double& settle) {
  SettingsReader in(node, file);
  in.read("max_translation", translation);
  in.read("max_yaw_deg", yaw);
  in.read("settle_iterations", settle);
  in.finish();
}

}  // namespace

BasinReportSettings read_basin_report_settings(const ExperimentConfig& config) {
  BasinReportSettings s;
  SettingsReader in(config.reference, config.file);
  {
    SettingsReader c(in.child("criterion"), config.file);
    c.read("translation_m", s.criterion.max_translation_m);
    c.read("rotation_deg", s.criterion.max_rotation_deg);
    c.finish();
    if (!(s.criterion.max_translation_m > 0) || !(s.criterion.max_rotation_deg > 0))
      c.fail("", "key 'criterion': translation_m and rotation_deg must be > 0");
  }
  in.read("basin_rate", s.basin_rate);
  if (!(s.basin_rate > 0 && s.basin_rate <= 1)) in.fail("basin_rate", "key 'basin_rate' must be in (0, 1]");
  {
    SettingsReader t(in.child("thesis"), config.file);
    read_thesis(t.child("ndt"), config.file, s.ndt_translation, s.ndt_yaw, s.ndt_settle);
    read_thesis(t.child("mlndt"), config.file, s.mlndt_translation, s.mlndt_yaw, s.mlndt_settle);
    t.finish();
  }
  {
    SettingsReader b(in.child("bands"), config.file);
    read_pair(b, "translation_ratio", s.translation_band);
    read_pair(b, "yaw_ratio", s.yaw_band);
    read_pair(b, "ndt_settle", s.ndt_settle_band);
    b.read("solver_success_difference", s.solver_difference);
    b.finish();
  }
  const auto names = [&](const char* key, const char* a, const char* b, std::string& x, std::string& y) {
    SettingsReader r(in.child(key), config.file);
    r.read(a, x);
    r.read(b, y);
    r.finish();
    for (const std::string* name : {&x, &y}) {
      if (name->empty()) continue;
      if (std::none_of(config.methods.begin(), config.methods.end(),
                       [&](const MethodConfig& m) { return m.name == *name; }))
        r.fail(name == &x ? a : b,
               "key '" + std::string(name == &x ? a : b) + "': no method named '" + *name + "'");
    }
  };
  names("compare_solvers", "newton", "lm", s.newton, s.lm);
  names("compare_start_layers", "first", "second", s.first_layer, s.second_layer);
  in.finish();
  return s;
}

long BasinData::method(const std::string& name) const {
  for (std::size_t m = 0; m < methods.size(); ++m) {
    if (methods[m] != name) continue;
    const bool any = std::any_of(runs.begin(), runs.end(), [&](const BasinRun& r) { return r.method == m; });
    return any ? static_cast<long>(m) : -1;
  }
  return -1;
}

void BasinData::paired(std::size_t a, std::size_t b, std::vector<bool>& sa, std::vector<bool>& sb) const {
  std::map<std::string, const BasinRun*> of_b;
  for (const BasinRun& r : runs)
    if (r.method == b) of_b[r.point] = &r;
  for (const BasinRun& r : runs) {
    if (r.method != a) continue;
    const auto it = of_b.find(r.point);
    if (it == of_b.end()) continue;
    sa.push_back(r.success);
    sb.push_back(it->second->success);
  }
}

void BasinData::paired_values(std::size_t a, std::size_t b, double BasinRun::*field, std::vector<double>& va,
                              std::vector<double>& vb) const {
  std::map<std::string, const BasinRun*> of_b;
  for (const BasinRun& r : runs)
    if (r.method == b && r.success) of_b[r.point] = &r;
  for (const BasinRun& r : runs) {
    if (r.method != a || !r.success) continue;
    const auto it = of_b.find(r.point);
    if (it == of_b.end()) continue;
    va.push_back(r.*field);
    vb.push_back(it->second->*field);
  }
}

std::vector<std::size_t> BasinData::active_scenes() const {
  std::vector<std::size_t> out;
  for (std::size_t s = 0; s < scenes.size(); ++s)
    if (std::isfinite(cell_edge[s])) out.push_back(s);
  return out;
}

std::vector<double> BasinData::values(std::size_t m, double BasinRun::*field, bool successes_only) const {
  std::vector<double> out;
  for (const BasinRun& r : runs)
    if (r.method == m && (r.success || !successes_only)) out.push_back(r.*field);
  return out;
}

BasinData basin_data(const ExperimentConfig& config, const RegistrationParams& params,
                     const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows) {
  BasinData d;
  d.config = &config;
  d.settings = read_basin_report_settings(config);
  for (const auto& m : config.methods) d.methods.push_back(m.name);
  const DisplacedSettings scenes = read_displaced_settings(config, params);
  d.cells = scenes.cells;
  for (const auto& s : scenes.scenes) d.scenes.push_back(s.name);
  d.cell_edge.assign(d.scenes.size(), NAN);
  d.runs = basin_runs(runs, rows, d.settings.criterion);
  std::vector<double> offsets, yaws;
  for (const BasinRun& r : d.runs) {
    offsets.push_back(r.offset);
    yaws.push_back(r.yaw);
    if (r.scene < d.cell_edge.size()) d.cell_edge[r.scene] = r.row->value(keys::kCellEdgeM);
  }
  d.offsets = distinct(offsets);
  d.yaws = distinct(yaws);
  d.translation.assign(d.methods.size(), std::vector<double>(d.scenes.size(), NAN));
  d.yaw = d.translation;
  for (std::size_t m = 0; m < d.methods.size(); ++m) {
    for (std::size_t s = 0; s < d.scenes.size(); ++s) {
      std::vector<double> tv, yv;
      std::vector<bool> ts, ys;
      for (const BasinRun& r : d.runs) {
        if (r.method != m || r.scene != s) continue;
        if (r.yaw == 0) {
          tv.push_back(r.offset);
          ts.push_back(r.success);
        }
        if (r.offset == 0) {
          yv.push_back(r.yaw);
          ys.push_back(r.success);
        }
      }
      d.translation[m][s] = basin_radius(tv, ts, d.settings.basin_rate);
      d.yaw[m][s] = basin_radius(yv, ys, d.settings.basin_rate);
    }
  }
  return d;
}

}  // namespace sextant
