// Layout (§5.2.1.1–5.2.1.3): per sweep point the maximum / final position errors
// (ours | thesis), consistency (NEES) and failures per filter; error norm, rotation error and NEES
// against the scan (figs 5.27–5.29, 5.31, 5.33–5.34, 5.37–5.38); the map with pose ellipses
// (fig 5.30); the sanity checks and the declared claims.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "kit/plane_slam_params.hpp"
#include "kit/row_keys.hpp"
#include "plane_slam/report.hpp"
#include "plane_slam/row_keys.hpp"
#include "sextant/eval/statistics.hpp"
#include "sextant/eval/verdict.hpp"
#include "sextant/experiments/experiment_config.hpp"

namespace sextant {
namespace accuracy_layout {

/// Method → the model of its own odometry (`odometry:` of the method), for the methods that have one.
std::map<std::string, std::string> own_odometry_models(const ExperimentConfig& config) {
  std::map<std::string, std::string> out;
  for (const MethodConfig& m : config.methods) {
    const PlaneSlamMethod pm = read_plane_slam_method(m.node, config.file);
    if (pm.odometry) out[m.name] = pm.odometry->model;
  }
  return out;
}

}  // namespace accuracy_layout

namespace {

Table error_table(const ExperimentConfig& config, const PlaneSlamRows& data, const std::string& point) {
  Table t;
  t.caption = "Maximum and final position error norms" + (point.empty() ? "" : ", " + point_text(point)) +
              " (ours: median over repetitions | thesis)";
  t.label = "errors" + point_stem(point);
  t.note =
      "errors are 3D position error norms [m]; inconsistent = share of scans with the pose NEES above the "
      "χ²₆ bound; failed = scans with a non-ok filter step (not positive definite, Cholesky, singular).";
  t.add_column("method")
      .add_compared_column("max error m", 2)
      .add_compared_column("at scan", 0)
      .add_number_column("final error m", 2)
      .add_number_column("mean error m", 2)
      .add_number_column("mean NEES", 1)
      .add_number_column("inconsistent %", 1)
      .add_number_column("failed scans", 0)
      .add_number_column("map size", 0);
  // The thesis' numbers only where it gives them (E13: P0 = 1e-6·I, not × 1e3 or × 1e6).
  const bool thesis_here = reference_at_point(config, point);
  if (!thesis_here && config.reference.IsMap() && config.reference["p0_scale"].IsScalar())
    t.note += " The thesis gives its numbers for " + point_text(config.reference["p0_scale"].Scalar()) +
              " only: n/a here.";
  const auto thesis = [&](const char* key, const std::string& name) {
    return thesis_here ? number_or_missing(reference_value(config, key, name)) : Cell::text("n/a");
  };
  const auto groups = data.at(point);
  // One odometry row per odometry model: the campus' (or resampled from it), and each model that
  // methods bring with `odometry:` (issue 27), taken from the first method driven by it.
  const std::map<std::string, std::string> own = accuracy_layout::own_odometry_models(config);
  std::set<std::string> shown;
  for (const MethodRows* g : groups) {
    const auto it = own.find(g->name);
    const std::string model = it == own.end() ? "" : it->second;
    if (!shown.insert(model).second) continue;
    const std::string name = model.empty() ? "odometry" : "odometry (" + model + ")";
    t.add_row(
        {Cell::text(name), number_or_missing(median_of(g->values("odometry_max_error_m"))),
         thesis("max_error_m", name), number_or_missing(median_of(g->values("odometry_max_error_scan"))),
         thesis("max_error_scan", name), number_or_missing(median_of(g->values(keys::kOdometryFinalErrorM))),
         number_or_missing(median_of(g->values(keys::kOdometryMeanErrorM)))});
  }
  for (const MethodRows* g : groups) {
    t.add_row({Cell::text(g->name), number_or_missing(median_of(g->values("max_error_m"))),
               thesis("max_error_m", g->name), number_or_missing(median_of(g->values("max_error_scan"))),
               thesis("max_error_scan", g->name), number_or_missing(median_of(g->values("final_error_m"))),
               number_or_missing(median_of(g->values("mean_error_m"))),
               number_or_missing(median_of(g->values("mean_nees"))),
               number_or_missing(100.0 * median_of(g->values("inconsistent_fraction"))),
               number_or_missing(median_of(g->values(keys::kFailedSteps))),
               number_or_missing(median_of(g->values(keys::kMapSize)))});
  }
  return t;
}

/// One row per (point, method): how often and how the filter failed (fig 5.31's P0 study).
Table failure_table(const PlaneSlamRows& data) {
  Table t;
  t.caption =
      "Filter failures per initial covariance scale P0 (fig 5.31: the UKF degrades at P0 × 1e3 and "
      "loses positive definiteness beyond)";
  t.label = "failures";
  t.note =
      "runs failed = repetitions with at least one non-ok filter step; of them, ended = runs in which the "
      "filter failed on more than half of its steps (with failures_are_results, E13, kept as rows; otherwise "
      "failed runs whose steps are not in the other columns); counts are summed over repetitions.";
  t.add_column("p0_scale")
      .add_column("method")
      .add_number_column("runs failed", 0)
      .add_number_column("of them ended", 0)
      .add_number_column("runs", 0)
      .add_number_column("not pos. def. steps", 0)
      .add_number_column("Cholesky failures", 0)
      .add_number_column("first failure scan", 0)
      .add_number_column("max error m (median)", 2)
      .add_number_column("final error m (median)", 2);
  for (const std::string& point : data.points) {
    for (const MethodRows& group : data.groups) {
      if (group.point != point || (group.rows.empty() && group.ended.empty())) continue;
      const MethodRows* g = &group;
      double ended = static_cast<double>(g->ended.size());
      double failed_runs = ended, npd = 0, chol = 0, first = NAN;
      for (const RunRow* r : g->rows) {
        if (r->value(keys::kEndedByFailures) > 0) ++ended;  // failures_are_results: kept as a row
        if (r->value(keys::kFailedSteps) > 0) ++failed_runs;
        npd += r->value(keys::kNotPositiveDefinite);
        chol += r->value(keys::kCholeskyFailures);
        const double f = r->value(keys::kFirstFailureScan);
        if (std::isfinite(f) && !(f >= first)) first = f;
      }
      t.add_row({Cell::text(point), Cell::text(g->name), Cell::number(failed_runs), Cell::number(ended),
                 Cell::number(static_cast<double>(g->rows.size() + g->ended.size())), Cell::number(npd),
                 Cell::number(chol), number_or_missing(first),
                 number_or_missing(median_of(g->values("max_error_m"))),
                 number_or_missing(median_of(g->values("final_error_m")))});
    }
  }
  return t;
}

ReportFigure nees_figure(const PlaneSlamRows& data, const PlaneSlamParams& params, const std::string& point) {
  XYPlot plot;
  plot.title = "Pose NEES per scan" + (point.empty() ? "" : " (" + point_text(point) + ")");
  plot.x_label = "scan";
  plot.y_label = "NEES (6 dof)";
  plot.log_y = true;
  std::size_t n = 0;
  double bound = NAN;
  for (const MethodRows* g : data.at(point)) {
    const auto& y = series_or_empty(*g->first(), keys::kNees);
    n = std::max(n, y.size());
    bound = g->first()->value(keys::kNeesBound);
    plot.add_line(g->name, scan_axis(y.size()), y);
  }
  distinguish_series(plot);  // the methods only: the bound stays a plain line
  if (n > 0 && std::isfinite(bound))
    plot.series.push_back({"χ²₆(" + format_number(params.nees_probability, 2, "n/a") + ") bound",
                           {0.0, double(n - 1)},
                           {bound, bound},
                           PlotSeries::Style::line,
                           "#d62728"});
  return {"nees" + point_stem(point),
          "Normalised estimation error squared of the pose per scan" +
              (point.empty() ? "" : ", " + point_text(point)) + ", against the χ²₆ bound (repetition 1)",
          render_svg(plot)};
}

}  // namespace

ReportSection accuracy_report(const ExperimentConfig& config, const PlaneSlamParams& params,
                              const PlaneSlamRows& data) {
  ReportSection section;
  section.notes = common_notes(config, params, data);
  if (auto sigma = plane_slam_sigma_point_table(config)) section.tables.push_back(*sigma);
  const std::map<std::string, std::string> own = accuracy_layout::own_odometry_models(config);
  for (const std::string& point : data.points) {
    section.tables.push_back(error_table(config, data, point));
    if (data.at(point).empty()) continue;
    section.figures.push_back(error_figure(data, point, keys::kErrorM, keys::kOdometryErrorM, "error_vs_scan",
                                           "position error norm [m]", "Position error norm per scan", own));
    section.figures.push_back(error_figure(data, point, keys::kRotationErrorDeg,
                                           keys::kOdometryRotationErrorDeg, "rotation_error_vs_scan",
                                           "rotation error norm [deg]", "Rotation error norm per scan", own));
    section.figures.push_back(nees_figure(data, params, point));
  }
  if (data.points.size() > 1) section.tables.push_back(failure_table(data));
  for (const MethodRows* g : data.at(data.points.front()))
    section.figures.push_back(map_figure(config, params, *g->first(), g->name, "map_" + g->name));
  section.claims = declared_claims(config, params, data);
  for (Claim& c : beats_odometry_claims(data, config.seed)) section.claims.push_back(c);
  return section;
}

}  // namespace sextant
