// E4 layout (§5.1.1.3, table 5.8): initial guess f · Z_gt × starting layer → fail rate %,
// registration time s and error norm cm (of the successes), ours | thesis, and the thesis'
// guideline (good guess → start at layer 4, f = 0.3 → layer 3, no guess → layer 2 or 3) as claims.
#include <algorithm>
#include <cmath>
#include <map>

#include "registration_report.hpp"

namespace sextant {
namespace {

struct Cellstats {
  double runs = 0, failures = 0, seconds = 0, error_sum = 0, error_count = 0;
  double fail_percent() const { return runs > 0 ? 100.0 * failures / runs : NAN; }
  double mean_seconds() const { return runs > 0 ? seconds / runs : NAN; }
  double mean_error() const { return error_count > 0 ? error_sum / error_count : NAN; }
};

/// A map entry whose key equals `value` numerically (YAML keys "0.9", "0", "4").
YAML::Node numeric_entry(const YAML::Node& map, double value) {
  if (!map.IsMap()) return YAML::Node();
  for (const auto& entry : map) {
    try {
      if (std::abs(entry.first.as<double>() - value) < 1e-9) return entry.second;
    } catch (const YAML::Exception&) {
    }
  }
  return YAML::Node();
}

std::vector<double> axis_numbers(const ExperimentConfig& config, const std::string& name) {
  for (const auto& axis : config.sweep) {
    if (axis.name != name) continue;
    std::vector<double> values;
    for (const auto& v : axis.values) values.push_back(v.as<double>());
    return values;
  }
  return {NAN};
}

double point_number(const RunSpec& run, const std::string& axis) {
  const auto it = run.point.find(axis);
  return it == run.point.end() ? NAN : std::stod(it->second);
}

bool same(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) || std::abs(a - b) < 1e-9;
}

}  // namespace

ReportSection init_layer_report(const ExperimentConfig& config, const RegistrationParams& params,
                                const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows) {
  const std::vector<double> fs = axis_numbers(config, "f"), layers = axis_numbers(config, "start_layer");
  // stats[method][f index][layer index]
  std::vector<std::vector<std::vector<Cellstats>>> stats(
      config.methods.size(),
      std::vector<std::vector<Cellstats>>(fs.size(), std::vector<Cellstats>(layers.size())));
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!rows[i] || !rows[i]->ok) continue;
    const double f = point_number(runs[i], "f"), s = point_number(runs[i], "start_layer");
    const auto fi = static_cast<std::size_t>(
        std::find_if(fs.begin(), fs.end(), [&](double v) { return same(v, f); }) - fs.begin());
    const auto li = static_cast<std::size_t>(
        std::find_if(layers.begin(), layers.end(), [&](double v) { return same(v, s); }) - layers.begin());
    if (fi >= fs.size() || li >= layers.size()) continue;
    Cellstats& c = stats[runs[i].method_index][fi][li];
    const bool success = rows[i]->value("success") > 0.5;
    c.runs += 1;
    c.failures += success ? 0 : 1;
    c.seconds += rows[i]->value("seconds_registration");
    if (success) {
      c.error_sum += rows[i]->value("translation_cm");
      c.error_count += 1;
    }
  }

  ReportSection section;
  section.notes =
      "Initial guess Z_init = f · Z_gt in parameter space; ML-NDT from start layer s to the last layer, 3 "
      "iterations per layer, "
      "the last until convergence. Fail = not (" +
      params.success + "); error = mean translation error of the successes [cm].";
  const YAML::Node thesis = child_or_null(config.reference, "table_5_8");
  for (std::size_t m = 0; m < config.methods.size(); ++m) {
    Table t;
    t.caption =
        "Table 5.8: initial guess quality × starting layer, " + config.methods[m].name + " (ours | thesis)";
    t.label = config.methods.size() == 1 ? "table_5_8" : "table_5_8_" + config.methods[m].name;
    t.note = "time = sampling + reference model + alignment [s] (ours C++, the thesis MATLAB).";
    t.add_column("f")
        .add_column("start layer")
        .add_compared_column("fail %", 0)
        .add_compared_column("time s", 3)
        .add_compared_column("error cm", 2);
    for (std::size_t fi = 0; fi < fs.size(); ++fi) {
      for (std::size_t li = 0; li < layers.size(); ++li) {
        const Cellstats& c = stats[m][fi][li];
        const YAML::Node ref = numeric_entry(numeric_entry(thesis, fs[fi]), layers[li]);
        const auto value = [&](std::size_t k) {
          return ref.IsSequence() && ref.size() == 3 ? Cell::number(ref[k].as<double>()) : Cell::missing();
        };
        t.add_row({Cell::text(format_number(fs[fi], 1)), Cell::text(format_number(layers[li], 0)),
                   number_or_missing(c.fail_percent()), value(0), number_or_missing(c.mean_seconds()),
                   value(1), number_or_missing(c.mean_error()), value(2)});
      }
    }
    section.tables.push_back(t);
  }

  // Claims on the first method: the guideline's best start layer per f, and "start at the last layer is
  // fastest".
  if (config.methods.empty()) return section;
  const auto& first = stats.front();
  const YAML::Node guideline = child_or_null(config.reference, "guideline");
  for (std::size_t fi = 0; fi < fs.size(); ++fi) {
    const YAML::Node expected = numeric_entry(guideline, fs[fi]);
    if (!expected.IsSequence()) continue;
    const auto best_layers = expected.as<std::vector<int>>();
    std::string listed;
    for (int l : best_layers) listed += (listed.empty() ? "" : " or ") + std::to_string(l);
    Claim c{"f = " + format_number(fs[fi], 1) + ": starting at layer " + listed +
                " is best (fewest failures, then fastest)",
            Verdict::not_comparable, ""};
    long best = -1;
    for (std::size_t li = 0; li < layers.size(); ++li) {
      const Cellstats& s = first[fi][li];
      if (s.runs == 0) continue;
      if (best < 0) {
        best = static_cast<long>(li);
        continue;
      }
      const Cellstats& b = first[fi][static_cast<std::size_t>(best)];
      if (s.fail_percent() < b.fail_percent() ||
          (s.fail_percent() == b.fail_percent() && s.mean_seconds() < b.mean_seconds()))
        best = static_cast<long>(li);
    }
    if (best >= 0) {
      const int ours = static_cast<int>(layers[static_cast<std::size_t>(best)]);
      c.verdict = std::find(best_layers.begin(), best_layers.end(), ours) != best_layers.end()
                      ? Verdict::holds
                      : Verdict::does_not_hold;
      c.evidence = "ours: layer " + std::to_string(ours) + ";";
      for (std::size_t li = 0; li < layers.size(); ++li)
        c.evidence += " s=" + format_number(layers[li], 0) + ": " +
                      format_number(first[fi][li].fail_percent(), 0) + " % / " +
                      format_number(first[fi][li].mean_seconds(), 3) + " s;";
    }
    section.claims.push_back(c);
  }
  const auto last = static_cast<std::size_t>(std::max_element(layers.begin(), layers.end()) - layers.begin());
  Claim fastest{
      "Starting at the last layer (" + format_number(layers[last], 0) + ") is the fastest for every f",
      Verdict::not_comparable, ""};
  std::size_t compared = 0, held = 0;
  for (std::size_t fi = 0; fi < fs.size(); ++fi) {
    bool ok = first[fi][last].runs > 0;
    for (std::size_t li = 0; li < layers.size() && ok; ++li) {
      if (first[fi][li].runs == 0) ok = false;
    }
    if (!ok) continue;
    ++compared;
    bool is_fastest = true;
    for (std::size_t li = 0; li < layers.size(); ++li)
      is_fastest = is_fastest && first[fi][last].mean_seconds() <= first[fi][li].mean_seconds();
    held += is_fastest ? 1 : 0;
  }
  if (compared > 0) {
    fastest.verdict = held == compared ? Verdict::holds : Verdict::does_not_hold;
    fastest.evidence =
        "fastest for " + std::to_string(held) + " of " + std::to_string(compared) + " values of f";
  }
  section.claims.push_back(fastest);
  return section;
}

}  // namespace sextant
