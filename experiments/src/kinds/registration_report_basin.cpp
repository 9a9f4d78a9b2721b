// E1 layout (§5.1.1.1, figs 5.1–5.6): per method a success-rate map over the initial offsets
// (translation tx × yaw), normalised score-vs-iteration curves, a basin table (ours | thesis) and
// the claims (ML-NDT's basin is wider, converges in fewer iterations, LM vs Newton).
#include <algorithm>
#include <cmath>
#include <map>

#include "registration_report.hpp"
#include "sextant/eval/plots.hpp"

namespace sextant {
namespace {

/// The values of one sweep axis as labels (the RunSpec point labels) and numbers; {"0"} when absent.
struct AxisValues {
  std::vector<std::string> labels;
  std::vector<double> values;
};

AxisValues axis_values(const std::vector<RunSpec>& runs, const std::string& axis) {
  std::map<double, std::string> seen;
  for (const auto& r : runs) {
    const auto it = r.point.find(axis);
    if (it != r.point.end()) seen.emplace(std::stod(it->second), it->second);
  }
  AxisValues out;
  if (seen.empty()) seen.emplace(0.0, "0");
  for (const auto& [v, label] : seen) {
    out.values.push_back(v);
    out.labels.push_back(label);
  }
  return out;
}

std::size_t index_of(const AxisValues& axis, const RunSpec& run, const std::string& name) {
  const auto it = run.point.find(name);
  if (it == run.point.end()) return 0;
  const double v = std::stod(it->second);
  return static_cast<std::size_t>(std::find(axis.values.begin(), axis.values.end(), v) - axis.values.begin());
}

struct Cellwise {
  Eigen::MatrixXd successes, counts, iterations;  ///< rows = yaw, cols = tx
};

/// Fraction of the runs inside |tx| ≤ max_tx and |yaw| ≤ max_yaw that succeeded (NaN when none).
double success_within(const Cellwise& c, const AxisValues& tx, const AxisValues& yaw, double max_tx,
                      double max_yaw) {
  double s = 0, n = 0;
  for (std::size_t r = 0; r < yaw.values.size(); ++r) {
    for (std::size_t k = 0; k < tx.values.size(); ++k) {
      if (std::abs(tx.values[k]) > max_tx + 1e-9 || std::abs(yaw.values[r]) > max_yaw + 1e-9) continue;
      s += c.successes(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(k));
      n += c.counts(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(k));
    }
  }
  return n > 0 ? s / n : NAN;
}

/// The largest |offset| along one axis (the other at 0) up to which every run succeeded.
double basin_extent(const Cellwise& c, const AxisValues& along, const AxisValues& other, bool along_columns) {
  const auto zero = static_cast<Eigen::Index>(std::find(other.values.begin(), other.values.end(), 0.0) -
                                              other.values.begin());
  if (zero >= static_cast<Eigen::Index>(other.values.size())) return NAN;
  std::vector<std::pair<double, bool>> points;  // |offset|, all succeeded
  for (std::size_t k = 0; k < along.values.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    const double n = along_columns ? c.counts(zero, i) : c.counts(i, zero);
    const double s = along_columns ? c.successes(zero, i) : c.successes(i, zero);
    if (n > 0) points.emplace_back(std::abs(along.values[k]), s == n);
  }
  std::sort(points.begin(), points.end());
  double extent = NAN;
  for (const auto& [offset, ok] : points) {
    if (!ok) break;
    extent = offset;
  }
  return extent;
}

}  // namespace

ReportSection basin_report(const ExperimentConfig& config, const RegistrationParams& params,
                           const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows) {
  const AxisValues tx = axis_values(runs, "tx"), yaw = axis_values(runs, "yaw");
  const auto R = static_cast<Eigen::Index>(yaw.values.size()),
             C = static_cast<Eigen::Index>(tx.values.size());
  std::vector<Cellwise> cells(
      config.methods.size(),
      Cellwise{Eigen::MatrixXd::Zero(R, C), Eigen::MatrixXd::Zero(R, C), Eigen::MatrixXd::Zero(R, C)});
  // The convergence curve of each method: the run at the smallest non-zero offsets, repetition 0.
  const std::size_t curve_tx = tx.values.size() > 1 ? 1 : 0, curve_yaw = yaw.values.size() > 1 ? 1 : 0;
  std::vector<std::vector<double>> curves(config.methods.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!rows[i] || !rows[i]->ok) continue;
    const auto r = static_cast<Eigen::Index>(index_of(yaw, runs[i], "yaw")),
               k = static_cast<Eigen::Index>(index_of(tx, runs[i], "tx"));
    Cellwise& c = cells[runs[i].method_index];
    c.counts(r, k) += 1;
    c.successes(r, k) += rows[i]->value("success");
    c.iterations(r, k) += rows[i]->value("iterations");
    if (static_cast<std::size_t>(r) == curve_yaw && static_cast<std::size_t>(k) == curve_tx &&
        runs[i].repetition == 0) {
      const auto it = rows[i]->series.find("score");
      if (it != rows[i]->series.end()) curves[runs[i].method_index] = it->second;
    }
  }

  ReportSection section;
  section.notes =
      "One pair (scans " + std::to_string(params.scan) + " → " + std::to_string(params.second) +
      ") whose input is displaced by tx [m] along x and a yaw [deg]; identity initial guess; success = " +
      params.success +
      ". The thesis gives its offsets in unnamed \"units\" on a mine scan; ours are metres on the campus.";
  const YAML::Node refs = child_or_null(config.reference, "methods");
  Table basin;
  basin.caption = "Convergence basin per method (ours | thesis)";
  basin.label = "basin";
  basin.note = "basin = largest offset along one axis (the other at 0) up to which every run succeeded.";
  basin.add_column("method")
      .add_number_column("success %", 1)
      .add_compared_column("basin tx", 2)
      .add_compared_column("basin yaw °", 1);
  basin.add_number_column("iterations (mean)", 1);
  for (std::size_t m = 0; m < config.methods.size(); ++m) {
    const std::string& name = config.methods[m].name;
    const Cellwise& c = cells[m];
    const double n = c.counts.sum();
    Heatmap map;
    map.title = "Success rate: " + name;
    map.x_label = "translation offset tx [m]";
    map.y_label = "rotation offset yaw [deg]";
    map.colorbar_label = "success rate";
    map.x_ticks = tx.labels;
    map.y_ticks = yaw.labels;
    map.values = Eigen::MatrixXd::Constant(R, C, NAN);
    for (Eigen::Index r = 0; r < R; ++r) {
      for (Eigen::Index k = 0; k < C; ++k) {
        if (c.counts(r, k) > 0) map.values(r, k) = c.successes(r, k) / c.counts(r, k);
      }
    }
    map.annotate = true;
    map.annotate_precision = 1;
    section.figures.push_back(
        {"success_map_" + name, "Success rate over the initial offsets, " + name, render_svg(map)});
    const YAML::Node ref = child_or_null(refs, name);
    basin.add_row({Cell::text(name), number_or_missing(n > 0 ? 100.0 * c.successes.sum() / n : NAN),
                   number_or_missing(basin_extent(c, tx, yaw, true)),
                   number_or_missing(reference_number(ref, "max_tx")),
                   number_or_missing(basin_extent(c, yaw, tx, false)),
                   number_or_missing(reference_number(ref, "max_yaw_deg")),
                   number_or_missing(n > 0 ? c.iterations.sum() / n : NAN)});
  }
  section.tables.push_back(basin);

  XYPlot plot;
  plot.title = "Normalised score vs iteration (tx = " + tx.labels[curve_tx] +
               " m, yaw = " + yaw.labels[curve_yaw] + "°)";
  plot.x_label = "iteration";
  plot.y_label = "(score − final) / (initial − final)";
  for (std::size_t m = 0; m < curves.size(); ++m) {
    const auto& s = curves[m];
    if (s.empty()) continue;
    const double span = s.front() - s.back();
    std::vector<double> x, y;
    for (std::size_t k = 0; k < s.size(); ++k) {
      x.push_back(static_cast<double>(k + 1));
      y.push_back(std::abs(span) > 0 ? (s[k] - s.back()) / span : 0.0);
    }
    plot.add_line(config.methods[m].name, x, y);
  }
  section.figures.push_back({"score_vs_iteration",
                             "Score against iteration for each method at one offset (figs 5.4–5.6)",
                             render_svg(plot)});

  // Claims.
  const auto method_index = [&](const std::string& name) -> long {
    for (std::size_t m = 0; m < config.methods.size(); ++m) {
      if (config.methods[m].name == name && cells[m].counts.sum() > 0) return static_cast<long>(m);
    }
    return -1;
  };
  const long b = method_index(params.baseline), p = method_index(params.proposed);
  Claim wider{
      params.proposed + " succeeds from more initial offsets than " + params.baseline + " (a wider basin)",
      Verdict::not_comparable, ""};
  Claim fewer{
      params.proposed + " converges in fewer iterations than " + params.baseline + " (thesis: a few vs ≈ 25)",
      Verdict::not_comparable, ""};
  if (b >= 0 && p >= 0) {
    const Cellwise &cb = cells[static_cast<std::size_t>(b)], &cp = cells[static_cast<std::size_t>(p)];
    wider.verdict = cp.successes.sum() >= cb.successes.sum() ? Verdict::holds : Verdict::does_not_hold;
    wider.evidence = format_number(cp.successes.sum(), 0) + " vs " + format_number(cb.successes.sum(), 0) +
                     " successful runs of " + format_number(cp.counts.sum(), 0);
    const double ip = cp.iterations.sum() / cp.counts.sum(), ib = cb.iterations.sum() / cb.counts.sum();
    fewer.verdict = ip < ib ? Verdict::holds : Verdict::does_not_hold;
    fewer.evidence = "mean " + format_number(ip, 1) + " vs " + format_number(ib, 1) + " iterations";
  }
  section.claims.push_back(wider);
  section.claims.push_back(fewer);
  for (std::size_t m = 0; m < config.methods.size(); ++m) {
    const YAML::Node ref = child_or_null(refs, config.methods[m].name);
    const auto max_tx = reference_number(ref, "max_tx"), max_yaw = reference_number(ref, "max_yaw_deg");
    if (!max_tx || !max_yaw) continue;
    const double rate = success_within(cells[m], tx, yaw, *max_tx, *max_yaw);
    Claim c{config.methods[m].name + " recovers offsets up to " + format_number(*max_tx, 0) +
                " in translation and " + format_number(*max_yaw, 0) +
                "° in rotation (≥ 90 % of those runs succeed)",
            std::isfinite(rate) ? (rate >= 0.9 ? Verdict::holds : Verdict::does_not_hold)
                                : Verdict::not_comparable,
            std::isfinite(rate)
                ? format_number(100.0 * rate, 1) + " % of the runs within that region succeeded"
                : "no run within that region"};
    section.claims.push_back(c);
  }
  const YAML::Node solvers = child_or_null(config.reference, "compare_solvers");
  if (solvers.IsMap() && solvers["newton"].IsDefined() && solvers["lm"].IsDefined()) {
    const long n = method_index(solvers["newton"].as<std::string>()),
               l = method_index(solvers["lm"].as<std::string>());
    Claim lm{"ML-NDT with LM needs fewer iterations than with Newton (\"LM is a little faster\")",
             Verdict::not_comparable, ""};
    if (n >= 0 && l >= 0) {
      const Cellwise &cn = cells[static_cast<std::size_t>(n)], &cl = cells[static_cast<std::size_t>(l)];
      const double in = cn.iterations.sum() / cn.counts.sum(), il = cl.iterations.sum() / cl.counts.sum();
      lm.verdict = il <= in ? Verdict::holds : Verdict::does_not_hold;
      lm.evidence = "mean " + format_number(il, 1) + " (LM) vs " + format_number(in, 1) +
                    " (Newton) iterations; success " + format_number(cl.successes.sum(), 0) + " vs " +
                    format_number(cn.successes.sum(), 0);
    }
    section.claims.push_back(lm);
  }
  return section;
}

}  // namespace sextant
