// E2 layout (§5.1.1.2 A): table 5.1 (odometry error), one table per method like 5.2 / 5.3
// (mean / std / max per parameter, ours | thesis), a time / iteration / success table like 5.4,
// the translation error against the scan index, and the thesis' claims with our verdicts.
#include <cmath>
#include <map>

#include "registration_report.hpp"
#include "sextant/eval/plots.hpp"

namespace sextant {
namespace {

struct MethodRows {
  std::string name;
  std::vector<const RunRow*> rows;
  RegistrationStats stats;
};

std::string table_label(const std::string& table, const std::string& fallback) {
  if (table.empty()) return fallback;
  std::string label = "table_" + table;
  for (char& c : label) {
    if (c == '.') c = '_';
  }
  return label;
}

std::string table_id(const YAML::Node& node) {
  return node.IsMap() && node["table"].IsDefined() ? node["table"].as<std::string>() : "";
}

Claim compare_claim(const std::string& statement, double ours_proposed, double ours_baseline,
                    bool larger_is_better, const std::string& unit, int precision) {
  Claim c{statement, Verdict::not_comparable, ""};
  if (!std::isfinite(ours_proposed) || !std::isfinite(ours_baseline)) return c;
  const bool holds = larger_is_better ? ours_proposed >= ours_baseline : ours_proposed <= ours_baseline;
  c.verdict = holds ? Verdict::holds : Verdict::does_not_hold;
  c.evidence = format_number(ours_proposed, precision) + unit + " vs " +
               format_number(ours_baseline, precision) + unit;
  return c;
}

}  // namespace

ReportSection accuracy_report(const ExperimentConfig& config, const RegistrationParams& params,
                              const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows) {
  const RegistrationStatsSettings settings = stats_settings(params);
  std::vector<MethodRows> methods(config.methods.size());
  for (std::size_t m = 0; m < methods.size(); ++m) methods[m].name = config.methods[m].name;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (rows[i] && rows[i]->ok) methods.at(runs[i].method_index).rows.push_back(rows[i]);
  }
  for (auto& m : methods) {
    std::vector<RegistrationSample> samples;
    for (const RunRow* r : m.rows) samples.push_back(sample_of(*r));
    m.stats = registration_stats(samples, settings);
  }

  ReportSection section;
  section.notes =
      "Relative-transform error E = T_gt⁻¹·T_est of consecutive pairs, translations in cm and angles in "
      "degrees (" +
      std::string(params.axes == AxisConvention::uos ? "uos axes, as the thesis" : "internal axes") +
      "); success = " + params.success +
      ". Times are our C++ wall times (the thesis': MATLAB); compare ratios, not values.";

  // Table 5.1: the odometry guess against the ground truth (every pair once: the first method's rows).
  const YAML::Node odometry_ref = child_or_null(config.reference, "odometry");
  std::vector<RegistrationSample> odometry;
  if (!methods.empty()) {
    for (const RunRow* r : methods.front().rows) {
      if (auto s = odometry_sample_of(*r)) odometry.push_back(*s);
    }
  }
  RegistrationStats odometry_stats;
  if (!odometry.empty()) {
    odometry_stats = registration_stats(odometry, settings);
    const ParameterReference ref = read_parameter_reference(odometry_ref, config.file);
    const std::string id = table_id(odometry_ref).empty() ? "5.1" : table_id(odometry_ref);
    section.tables.push_back(registration_error_table(
        odometry_stats, odometry_ref.IsMap() ? &ref : nullptr,
        "Table " + id + ": odometry relative error (ours | thesis)", table_label(id, "odometry")));
  }

  // Tables 5.2 / 5.3 (and PCL peers as extra tables).
  const YAML::Node method_refs = child_or_null(config.reference, "methods");
  for (const auto& m : methods) {
    const YAML::Node ref_node = child_or_null(method_refs, m.name);
    const ParameterReference ref = read_parameter_reference(ref_node, config.file);
    const std::string id = table_id(ref_node);
    const std::string caption =
        (id.empty() ? std::string("Relative error of ") : "Table " + id + ": relative error of ") + m.name +
        " (ours | thesis)";
    section.tables.push_back(registration_error_table(m.stats, ref_node.IsMap() ? &ref : nullptr, caption,
                                                      table_label(id, "errors_" + m.name)));
  }

  // Like table 5.4, with the success rate.
  Table summary;
  summary.caption =
      "Like table 5.4: success rate, registration time and iterations per method (ours | thesis)";
  summary.label = "table_5_4";
  summary.note =
      "time = sampling + reference model + alignment [s]; matched = points with a cell / correspondence [%].";
  summary.add_column("method")
      .add_compared_column("success %", 1)
      .add_compared_column("time s", 3)
      .add_compared_column("time std s", 3);
  summary.add_compared_column("iterations", 2)
      .add_number_column("matched %", 1)
      .add_number_column("kept %", 1)
      .add_number_column("pairs", 0);
  for (const auto& m : methods) {
    const YAML::Node ref = child_or_null(method_refs, m.name);
    double kept = 0;
    for (const RunRow* r : m.rows) kept += r->value("kept_fraction");
    summary.add_row(
        {Cell::text(m.name), number_or_missing(m.stats.count ? 100.0 * m.stats.success_rate : NAN),
         number_or_missing(reference_number(ref, "success_percent")),
         number_or_missing(m.stats.count ? m.stats.seconds.mean : NAN),
         number_or_missing(reference_number(ref, "seconds")),
         number_or_missing(m.stats.count ? m.stats.seconds.std : NAN),
         number_or_missing(reference_number(ref, "seconds_std")),
         number_or_missing(m.stats.count ? m.stats.iterations.mean : NAN),
         number_or_missing(reference_number(ref, "iterations")),
         number_or_missing(m.stats.matched_percent.count ? m.stats.matched_percent.mean : NAN),
         number_or_missing(m.rows.empty() ? NAN : 100.0 * kept / static_cast<double>(m.rows.size())),
         Cell::number(static_cast<double>(m.stats.count))});
  }
  section.tables.push_back(summary);

  // Figure: translation error against the reference scan index (figs 5.7–5.10).
  XYPlot plot;
  plot.title = "Translation error per pair";
  plot.x_label = "reference scan index";
  plot.y_label = "translation error [cm]";
  plot.log_y = true;
  if (!odometry.empty()) {
    std::vector<double> x, y;
    for (std::size_t k = 0; k < methods.front().rows.size() && k < odometry_stats.errors.size(); ++k) {
      x.push_back(methods.front().rows[k]->value("reference_scan"));
      y.push_back(odometry_stats.errors[k].translation_cm);
    }
    plot.add_scatter("odometry", x, y);
  }
  for (const auto& m : methods) {
    std::vector<double> x, y;
    for (std::size_t k = 0; k < m.rows.size(); ++k) {
      x.push_back(m.rows[k]->value("reference_scan"));
      y.push_back(m.stats.errors[k].translation_cm);
    }
    plot.add_scatter(m.name, x, y);
  }
  section.figures.push_back(
      {"error_vs_scan", "Translation error of every pair (log scale), per method and for the odometry guess",
       render_svg(plot)});

  // Claims: the proposed method against the baseline, and both against the odometry.
  const auto find = [&](const std::string& name) -> const MethodRows* {
    for (const auto& m : methods) {
      if (m.name == name && m.stats.count > 0) return &m;
    }
    return nullptr;
  };
  const MethodRows* base = find(params.baseline);
  const MethodRows* prop = find(params.proposed);
  const std::string pn = params.proposed.empty() ? "proposed" : params.proposed,
                    bn = params.baseline.empty() ? "baseline" : params.baseline;
  const auto stat = [](const MethodRows* m, auto get) { return m ? get(m->stats) : NAN; };
  section.claims.push_back(compare_claim(
      pn + " success rate ≥ " + bn + " success rate (thesis: ≈ 98 % vs ≈ 90 %)",
      stat(prop, [](const RegistrationStats& s) { return 100.0 * s.success_rate; }),
      stat(base, [](const RegistrationStats& s) { return 100.0 * s.success_rate; }), true, " %", 1));
  Claim faster =
      compare_claim(pn + " is faster than " + bn + " (thesis: ≈ 4×, 9.43 s vs 39.81 s)",
                    stat(prop, [](const RegistrationStats& s) { return s.seconds.mean; }),
                    stat(base, [](const RegistrationStats& s) { return s.seconds.mean; }), false, " s", 3);
  if (prop && base && prop->stats.seconds.mean > 0)
    faster.evidence +=
        " (ratio " + format_number(base->stats.seconds.mean / prop->stats.seconds.mean, 2) + "×)";
  section.claims.push_back(faster);
  section.claims.push_back(
      compare_claim(pn + " needs fewer iterations than " + bn + " (thesis: 12.77 vs 25)",
                    stat(prop, [](const RegistrationStats& s) { return s.iterations.mean; }),
                    stat(base, [](const RegistrationStats& s) { return s.iterations.mean; }), false, "", 2));
  if (!odometry.empty()) {
    for (const MethodRows* m : {base, prop}) {
      if (!m) continue;
      section.claims.push_back(compare_claim(
          m->name + " improves on the odometry guess (median translation error)",
          m->stats.translation_cm.median, odometry_stats.translation_cm.median, false, " cm", 2));
    }
  }
  return section;
}

}  // namespace sextant
