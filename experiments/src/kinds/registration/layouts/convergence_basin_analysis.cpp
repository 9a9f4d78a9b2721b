#include "registration/layouts/convergence_basin_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "kit/row_keys.hpp"
#include "registration/report.hpp"
#include "registration/row_keys.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"
#include "sextant/experiments/run_row.hpp"

namespace sextant {
namespace {

double label_value(const RunSpec& run, const char* axis) {
  const auto it = run.point.find(axis);
  return it == run.point.end() ? 0.0 : std::stod(it->second);
}

std::string point_key(const RunSpec& run) {
  std::string key;
  for (const auto& [axis, label] : run.point) key += axis + "=" + label + ";";
  return key + "rep=" + std::to_string(run.repetition);
}

}  // namespace

std::vector<std::pair<double, double>> iterate_errors(const RunRow& row) {
  const Eigen::Isometry3d truth = series_to_isometry(series_or_empty(row, keys::kGroundTruth));
  const std::vector<double>& xi = series_or_empty(row, keys::kTraceXi);
  std::vector<std::pair<double, double>> out;
  const auto add = [&](const Eigen::Isometry3d& T) {
    const Eigen::Isometry3d E = truth.inverse() * T;
    out.emplace_back(translation_norm(E), rotation_angle(E) * kDegPerRad);
  };
  add(series_to_isometry(series_or_empty(row, keys::kInitial)));
  for (std::size_t k = 0; k + 6 <= xi.size(); k += 6) {
    Vector6d v;
    for (int j = 0; j < 6; ++j) v[j] = xi[k + static_cast<std::size_t>(j)];
    add(to_isometry(Pose6::from_vector(v)));
  }
  return out;
}

double settle_iteration(const std::vector<std::pair<double, double>>& errors, const BasinCriterion& c) {
  if (errors.empty() || !c.ok(errors.back().first, errors.back().second)) return kNaN;
  std::size_t k = errors.size() - 1;
  while (k > 0 && c.ok(errors[k - 1].first, errors[k - 1].second)) --k;
  return static_cast<double>(k);
}

double iterations_in_last_layer(const RunRow& row) {
  const std::vector<double>& layer = series_or_empty(row, keys::kLayer);
  if (layer.empty()) return row.value(keys::kIterations);
  std::size_t k = 0;
  while (k < layer.size() && layer[layer.size() - 1 - k] == layer.back()) ++k;
  return static_cast<double>(k);
}

double post_settle_jitter_cm(const RunRow& row, double settle) {
  if (!std::isfinite(settle)) return kNaN;
  const std::vector<double>& xi = series_or_empty(row, keys::kTraceXi);
  const std::size_t n = xi.size() / 6;  // iterates 1..n are trace entries 0..n-1
  double sum = 0;
  int count = 0;
  for (auto k = static_cast<std::size_t>(std::max(1.0, settle)); k < n; ++k) {
    const std::size_t a = 6 * (k - 1), b = 6 * k;
    sum += 100.0 * std::hypot(xi[b] - xi[a], xi[b + 1] - xi[a + 1], xi[b + 2] - xi[a + 2]);
    ++count;
  }
  return count > 0 ? sum / count : 0.0;
}

std::vector<BasinRun> basin_runs(const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows,
                                 const BasinCriterion& criterion) {
  std::vector<BasinRun> out;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!rows[i] || !rows[i]->ok) continue;
    const RunRow& row = *rows[i];
    BasinRun r;
    r.method = runs[i].method_index;
    r.scene = static_cast<std::size_t>(std::max(0.0, row.value(keys::kScene)));
    r.offset = label_value(runs[i], "offset") + label_value(runs[i], "tx");
    r.yaw = std::abs(label_value(runs[i], "yaw"));
    r.direction = static_cast<int>(label_value(runs[i], "direction"));
    r.repetition = runs[i].repetition;
    r.point = point_key(runs[i]);
    r.success = criterion.ok(row.value(keys::kTranslationCm) / 100.0, row.value(keys::kRotationDeg));
    r.iterations = row.value(keys::kIterations);
    r.seconds = row.value(keys::kSecondsRegistration);
    r.settle = r.success ? settle_iteration(iterate_errors(row), criterion) : kNaN;
    r.jitter_cm = post_settle_jitter_cm(row, r.settle);
    r.last_layer_iterations = iterations_in_last_layer(row);
    r.row = &row;
    out.push_back(r);
  }
  return out;
}

std::vector<double> distinct(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

double basin_radius(const std::vector<double>& values, const std::vector<bool>& successes, double rate) {
  std::map<double, std::pair<double, double>> at;  // value → (successes, runs)
  for (std::size_t k = 0; k < values.size() && k < successes.size(); ++k) {
    at[values[k]].first += successes[k] ? 1.0 : 0.0;
    at[values[k]].second += 1.0;
  }
  if (at.empty()) return kNaN;
  double radius = 0.0;
  for (const auto& [value, count] : at) {
    if (count.first < rate * count.second) break;
    radius = value;
  }
  return radius;
}

std::vector<double> normalise_per_layer(const std::vector<double>& score, const std::vector<double>& layer) {
  std::vector<double> out;
  std::size_t begin = 0;
  while (begin < score.size()) {
    std::size_t end = begin + 1;
    while (end < score.size() && end < layer.size() && layer[end] == layer[begin]) ++end;
    const double first = score[begin], last = score[end - 1], span = first - last;
    for (std::size_t k = begin; k < end; ++k)
      out.push_back(std::abs(span) > 0 ? (score[k] - last) / span : 0.0);
    begin = end;
  }
  return out;
}

}  // namespace sextant
