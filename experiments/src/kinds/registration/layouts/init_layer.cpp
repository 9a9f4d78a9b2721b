// Layout (§5.1.1.3, table 5.8): initial guess f · Z_gt × starting layer → fail rate %,
// registration time s and error norm cm (of the successes), ours | thesis, per method; heat maps
// of fail rate and time over (f, start layer); the adaptive starting layer (a method with
// adaptive_start: one run per f over the whole sequence) as an extra row; and the thesis'
// guideline (good guess → layer 4, f = 0.3 → layer 3, no guess → layer 2 or 3) as claims decided
// on paired tests.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "registration/claims.hpp"
#include "registration/deviations.hpp"
#include "registration/report.hpp"
#include "registration/row_keys.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/eval/plots.hpp"

namespace sextant {
namespace {

/// The runs of one (method, f, start layer) cell, keyed by pair so that cells compare paired.
struct CellRuns {
  std::map<double, bool> success;  ///< pair → success
  std::vector<double> seconds, errors;
  double fail_percent() const {
    if (success.empty()) return NAN;
    double failures = 0;
    for (const auto& [pair, ok] : success) failures += ok ? 0 : 1;
    return 100.0 * failures / static_cast<double>(success.size());
  }
  double mean_seconds() const {
    double s = 0;
    for (double v : seconds) s += v;
    return seconds.empty() ? NAN : s / static_cast<double>(seconds.size());
  }
  double mean_error() const {
    double s = 0;
    for (double v : errors) s += v;
    return errors.empty() ? NAN : s / static_cast<double>(errors.size());
  }
  void add(double pair, bool ok, double seconds_, double error_cm) {
    success[pair] = ok;
    seconds.push_back(seconds_);
    if (ok) errors.push_back(error_cm);
  }
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

std::size_t index_of(const std::vector<double>& values, double v) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if ((std::isnan(v) && std::isnan(values[i])) || std::abs(values[i] - v) < 1e-9) return i;
  }
  return values.size();
}

/// Paired successes of two cells over the pairs both have.
PairedRates paired(const CellRuns& a, const CellRuns& b) {
  std::vector<bool> va, vb;
  for (const auto& [pair, ok] : a.success) {
    const auto it = b.success.find(pair);
    if (it == b.success.end()) continue;
    va.push_back(ok);
    vb.push_back(it->second);
  }
  return compare_paired_successes(va, vb);
}

/// Is starting at `cand` better than at `other`? Fewer failures first (paired); when that is
/// inconclusive, the faster median time (bootstrap ratio); inconclusive if neither decides.
Verdict better_layer(const CellRuns& cand, const CellRuns& other, std::uint64_t seed, std::string& evidence) {
  const PairedRates r = paired(cand, other);
  const Verdict by_failures = verdict_greater(r.difference, 0.0);
  evidence += " success " + describe(r.difference, "", 2);
  if (by_failures == Verdict::holds || by_failures == Verdict::does_not_hold) return by_failures;
  const Interval ratio = bootstrap_ratio_of_medians(other.seconds, cand.seconds, seed);
  evidence += ", time ratio " + describe(ratio, "×", 2);
  return verdict_greater(ratio, 1.0);
}

}  // namespace

ReportSection init_layer_report(const ExperimentConfig& config, const RegistrationParams& params,
                                const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows) {
  const std::vector<double> fs = axis_numbers(config, "f"), layers = axis_numbers(config, "start_layer");
  std::vector<RegistrationMethod> methods;
  for (const auto& m : config.methods) methods.push_back(read_registration_method(m.node, config.file));
  // cells[method][f][layer]; an adaptive method fills one column (index 0) from its sequence runs.
  std::vector<std::vector<std::vector<CellRuns>>> cells(
      methods.size(), std::vector<std::vector<CellRuns>>(fs.size(), std::vector<CellRuns>(layers.size())));
  std::vector<std::vector<std::map<int, int>>> adaptive_layers(methods.size(),
                                                               std::vector<std::map<int, int>>(fs.size()));
  std::vector<std::vector<std::array<int, 3>>> rule_counts(
      methods.size(), std::vector<std::array<int, 3>>(fs.size(), {0, 0, 0}));
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!rows[i] || !rows[i]->ok) continue;
    const RunRow& row = *rows[i];
    const std::size_t m = runs[i].method_index;
    const std::size_t fi = index_of(fs, point_value(runs[i], "f", NAN));
    if (fi >= fs.size()) continue;
    if (methods[m].adaptive) {
      const auto series = [&](const char* name) { return series_or_empty(row, name); };
      const auto pair = series(keys::kAdaptivePair), ok = series("adaptive_success"),
                 secs = series("adaptive_seconds_registration"), err = series("adaptive_translation_cm"),
                 layer = series(keys::kAdaptiveStartLayer), rule = series(keys::kAdaptiveRuleFailure);
      for (std::size_t k = 0;
           k < pair.size() && k < ok.size() && k < secs.size() && k < err.size() && k < layer.size(); ++k) {
        cells[m][fi][0].add(pair[k], ok[k] > 0.5, secs[k], err[k]);
        adaptive_layers[m][fi][static_cast<int>(layer[k])] += 1;
        if (k <
            rule.size()) {  // the rule's odometry test against the truth: [flagged, flagged ∧ failed, failed]
          auto& c = rule_counts[m][fi];
          const bool flagged = rule[k] > 0.5, failed = ok[k] < 0.5;
          c[0] += flagged ? 1 : 0;
          c[1] += flagged && failed ? 1 : 0;
          c[2] += failed ? 1 : 0;
        }
      }
      continue;
    }
    const std::size_t li = index_of(layers, point_value(runs[i], "start_layer", NAN));
    if (li >= layers.size()) continue;
    cells[m][fi][li].add(row.value(keys::kReferenceScan), row.value(keys::kSuccess) > 0.5,
                         row.value(keys::kSecondsRegistration), row.value(keys::kTranslationCm));
    pairs = std::max(pairs, cells[m][fi][li].success.size());
  }

  // Each adaptive method's base: the fixed-layer method whose config gives the same matcher settings,
  // else the first.
  const auto settings_text = [&](std::size_t m) { return YAML::Dump(config.methods[m].node["settings"]); };
  std::vector<std::size_t> base_of(methods.size(), methods.size());
  for (std::size_t a = 0; a < methods.size(); ++a) {
    if (!methods[a].adaptive) continue;
    std::size_t fallback = methods.size();
    for (std::size_t b = 0; b < methods.size(); ++b) {
      if (methods[b].adaptive) continue;
      if (fallback == methods.size()) fallback = b;
      if (base_of[a] == methods.size() && settings_text(b) == settings_text(a)) base_of[a] = b;
    }
    if (base_of[a] == methods.size()) base_of[a] = fallback;
  }

  ReportSection section;
  section.notes =
      "Profile: " + std::string(config.quick ? "quick" : "full") + " (n = " + std::to_string(pairs) +
      " pairs per cell)." + dataset_note(config) +
      " Initial guess Z_init = f · Z_gt in parameter space; ML-NDT from start layer s "
      "to the last layer, 3 iterations per layer, the last until convergence. Fail = not (" +
      params.success +
      "); error = mean translation error of the successes [cm]. The adaptive rows follow the thesis' "
      "proposal literally: start at the last layer; a registration fails the rule when it differs from "
      "the odometry by > 1 m or > 15°; above a 5 % running failure rate start at layer 3, above 20 % at "
      "layer 2 (state carried from pair to pair, one run per f over the whole sequence). Best-layer "
      "claims: a layer beats another when its paired success rate is higher (Newcombe interval above 0); "
      "when that is inconclusive, when its median time is lower (bootstrap ratio above 1).\n" +
      deviations_note(config);
  const YAML::Node thesis = child_or_null(config.reference, "table_5_8");
  for (std::size_t m = 0; m < methods.size(); ++m) {
    Table t;
    t.caption = "Table 5.8: initial guess quality × starting layer, " + methods[m].name + " (ours | thesis)";
    t.label = methods.size() == 1 ? "table_5_8" : "table_5_8_" + methods[m].name;
    t.note = "time = sampling + reference model + alignment [s] (ours C++, the thesis MATLAB).";
    if (methods[m].adaptive)
      t.note +=
          " Start layer: the layers the rule chose (layer: pairs). The rule's failure test compares the "
          "estimate with the odometry (> 1 m or > 15°), so a poor odometry flags correct registrations:";
    t.add_column("f")
        .add_column("start layer")
        .add_compared_column("fail %", 0)
        .add_compared_column("time s", 3)
        .add_compared_column("error cm", 2);
    for (std::size_t fi = 0; fi < fs.size(); ++fi) {
      for (std::size_t li = 0; li < (methods[m].adaptive ? 1 : layers.size()); ++li) {
        const CellRuns& c = cells[m][fi][li];
        std::string label = format_number(layers[li], 0);
        YAML::Node ref = numeric_entry(numeric_entry(thesis, fs[fi]), layers[li]);
        if (methods[m].adaptive) {
          label = "adaptive (";
          for (const auto& [layer, count] : adaptive_layers[m][fi])
            label += std::to_string(layer) + ":" + std::to_string(count) + " ";
          label.back() = ')';
          ref = YAML::Node();
        }
        const auto value = [&](std::size_t k) {
          return ref.IsSequence() && ref.size() == 3 ? Cell::number(ref[k].as<double>()) : Cell::missing();
        };
        if (methods[m].adaptive) {
          const auto& rc = rule_counts[m][fi];
          t.note += " f = " + format_number(fs[fi], 1) + ": the rule flagged " + std::to_string(rc[0]) +
                    " pairs, " + std::to_string(rc[1]) + " of them true failures (of " +
                    std::to_string(rc[2]) + ") —";
        }
        t.add_row({Cell::text(format_number(fs[fi], 1)), Cell::text(label),
                   number_or_missing(c.fail_percent()), value(0), number_or_missing(c.mean_seconds()),
                   value(1), number_or_missing(c.mean_error()), value(2)});
      }
    }
    section.tables.push_back(t);
  }

  // Heat maps of fail rate and time over (f, start layer); the adaptive methods as extra columns.
  for (const bool time : {false, true}) {
    for (std::size_t m = 0; m < methods.size(); ++m) {
      if (methods[m].adaptive) continue;
      Heatmap map;
      map.title = methods[m].name + (time ? ": mean registration time [s]" : ": fail rate [%]");
      map.x_label = "start layer";
      map.y_label = "f (Z_init = f · Z_gt)";
      map.colorbar_label = time ? "time [s]" : "fail rate [%]";
      for (double l : layers) map.x_ticks.push_back(format_number(l, 0));
      std::vector<std::size_t> extra;
      for (std::size_t a = 0; a < methods.size(); ++a) {
        if (methods[a].adaptive && base_of[a] == m) {
          extra.push_back(a);
          map.x_ticks.push_back("adaptive");
        }
      }
      for (double f : fs) map.y_ticks.push_back(format_number(f, 1));
      map.values = Eigen::MatrixXd::Constant(static_cast<Eigen::Index>(fs.size()),
                                             static_cast<Eigen::Index>(layers.size() + extra.size()), NAN);
      for (std::size_t fi = 0; fi < fs.size(); ++fi) {
        const auto r = static_cast<Eigen::Index>(fi);
        for (std::size_t li = 0; li < layers.size(); ++li)
          map.values(r, static_cast<Eigen::Index>(li)) =
              time ? cells[m][fi][li].mean_seconds() : cells[m][fi][li].fail_percent();
        for (std::size_t e = 0; e < extra.size(); ++e)
          map.values(r, static_cast<Eigen::Index>(layers.size() + e)) =
              time ? cells[extra[e]][fi][0].mean_seconds() : cells[extra[e]][fi][0].fail_percent();
      }
      map.value_min = 0;
      map.value_max =
          time ? std::max(1e-3, map.values.array().isNaN().select(0, map.values).maxCoeff()) : 100.0;
      map.annotate = true;
      map.annotate_precision = time ? 3 : 0;
      section.figures.push_back({std::string(time ? "heatmap_time_" : "heatmap_fail_") + methods[m].name,
                                 map.title + " over (f, start layer); adaptive rows as extra columns",
                                 render_svg(map)});
    }
  }

  // Claims: the guideline's best start layers per f, for every fixed-layer method.
  const YAML::Node guideline = child_or_null(config.reference, "guideline");
  std::uint64_t seed_k = 0;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    if (methods[m].adaptive) continue;
    for (std::size_t fi = 0; fi < fs.size(); ++fi) {
      const YAML::Node expected = numeric_entry(guideline, fs[fi]);
      if (!expected.IsSequence()) continue;
      const auto best = expected.as<std::vector<int>>();
      std::string listed;
      for (int l : best) listed += (listed.empty() ? "" : " or ") + std::to_string(l);
      Claim c{methods[m].name + ", f = " + format_number(fs[fi], 1) + ": starting at layer " + listed +
                  " is best (fewest failures, then fastest)",
              Verdict::not_comparable, ""};
      // The best verdict among the listed layers (holds > inconclusive > does not hold), each
      // listed layer compared against every layer not listed; ties broken by listing order.
      Verdict overall = Verdict::not_comparable;
      for (int cand : best) {
        const std::size_t ci = index_of(layers, cand);
        if (ci >= layers.size() || cells[m][fi][ci].success.empty()) continue;
        std::vector<Verdict> vs;
        std::string evidence = "layer " + std::to_string(cand) + " (fail " +
                               format_number(cells[m][fi][ci].fail_percent(), 0) + " %) vs";
        for (std::size_t li = 0; li < layers.size(); ++li) {
          if (std::find(best.begin(), best.end(), static_cast<int>(layers[li])) != best.end()) continue;
          if (cells[m][fi][li].success.empty()) continue;
          evidence += " layer " + format_number(layers[li], 0) + " (fail " +
                      format_number(cells[m][fi][li].fail_percent(), 0) + " %):";
          vs.push_back(
              better_layer(cells[m][fi][ci], cells[m][fi][li], claim_seed(config, 100 + seed_k++), evidence));
          evidence += ";";
        }
        const Verdict v = verdict_all(vs);
        const auto rank = [](Verdict x) {
          return x == Verdict::holds           ? 3
                 : x == Verdict::inconclusive  ? 2
                 : x == Verdict::does_not_hold ? 1
                                               : 0;
        };
        if (rank(v) > rank(overall)) overall = v;
        c.evidence += (c.evidence.empty() ? "" : " | ") + evidence;
      }
      c.verdict = overall;
      section.claims.push_back(c);
    }
    // "Starting at the last layer is the fastest for every f": median time ratio (other / last) > 1.
    const auto last =
        static_cast<std::size_t>(std::max_element(layers.begin(), layers.end()) - layers.begin());
    Claim fastest{methods[m].name + ": starting at the last layer (" + format_number(layers[last], 0) +
                      ") is the fastest for every f",
                  Verdict::not_comparable, ""};
    std::vector<Verdict> vs;
    for (std::size_t fi = 0; fi < fs.size(); ++fi) {
      for (std::size_t li = 0; li < layers.size(); ++li) {
        if (li == last || cells[m][fi][li].seconds.empty() || cells[m][fi][last].seconds.empty()) continue;
        const Interval ratio = bootstrap_ratio_of_medians(
            cells[m][fi][li].seconds, cells[m][fi][last].seconds, claim_seed(config, 100 + seed_k++));
        vs.push_back(verdict_greater(ratio, 1.0));
        fastest.evidence += "f = " + format_number(fs[fi], 1) + ", layer " + format_number(layers[li], 0) +
                            " / last: " + describe(ratio, "×") + "; ";
      }
    }
    fastest.verdict = verdict_all(vs);
    section.claims.push_back(fastest);
  }

  // The adaptive rule against the best fixed layer of its base method (the fixed-layer method with
  // the same matcher settings, else the first one): non-inferior within 5 points of success rate.
  for (std::size_t a = 0; a < methods.size(); ++a) {
    if (!methods[a].adaptive) continue;
    const std::size_t base = base_of[a];
    if (base == methods.size()) continue;
    Claim c{methods[a].name +
                ": the adaptive starting layer (§5.1.1.3, proposed) is within 5 points of the best fixed "
                "layer's success rate of " +
                methods[base].name + " for every f",
            Verdict::not_comparable, ""};
    std::vector<Verdict> vs;
    for (std::size_t fi = 0; fi < fs.size(); ++fi) {
      std::size_t best = layers.size();
      for (std::size_t li = 0; li < layers.size(); ++li) {
        if (cells[base][fi][li].success.empty()) continue;
        if (best == layers.size() ||
            cells[base][fi][li].fail_percent() < cells[base][fi][best].fail_percent())
          best = li;
      }
      if (best == layers.size() || cells[a][fi][0].success.empty()) continue;
      const PairedRates r = paired(cells[a][fi][0], cells[base][fi][best]);
      vs.push_back(verdict_greater(r.difference, -0.05));
      c.evidence += "f = " + format_number(fs[fi], 1) + " vs layer " + format_number(layers[best], 0) + ": " +
                    describe(r) + "; ";
    }
    c.verdict = verdict_all(vs);
    c.kind = ClaimKind::sanity;
    section.claims.push_back(c);
  }
  return section;
}

// The check of the layout's `reference:` block (InputError with file, line, key).
namespace init_layer_reference {

void check_layer_row(const YAML::Node& node, const std::string& file) {
  if (!node.IsMap())
    throw InputError(file, at_line(yaml_line(node)),
                     "key 'table_5_8': each f maps start layer → [fail %, time s, error cm]");
  for (const auto& entry : node) {
    try {
      (void)entry.first.as<int>();
      const auto v = entry.second.as<std::vector<double>>();
      if (v.size() != 3) throw YAML::Exception(YAML::Mark::null_mark(), "size");
    } catch (const YAML::Exception&) {
      throw InputError(file, at_line(yaml_line(entry.second)),
                       "key 'table_5_8': expected start layer: [fail %, time s, error cm]");
    }
  }
}

void check_guideline(const YAML::Node& node, const std::string& file) {
  try {
    (void)node.as<std::vector<int>>();
  } catch (const YAML::Exception&) {
    throw InputError(file, at_line(yaml_line(node)),
                     "key 'guideline': each f maps to the list of best start layers");
  }
}

}  // namespace init_layer_reference

void check_init_layer_reference(const ExperimentConfig& config) {
  SettingsReader in(config.reference, config.file);
  check_map_of(in.child("table_5_8"), config.file, "table_5_8", init_layer_reference::check_layer_row);
  check_map_of(in.child("guideline"), config.file, "guideline", init_layer_reference::check_guideline);
  in.finish();
}

}  // namespace sextant
