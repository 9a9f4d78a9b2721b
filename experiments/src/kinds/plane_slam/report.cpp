// Helpers shared by the plane_slam report layouts: rows grouped by method and sweep point, series
// access, the error-per-scan figure, the map figure and the beats-the-odometry sanity checks.
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "kit/filter_parameters.hpp"
#include "kit/reference_values.hpp"
#include "kit/row_keys.hpp"
#include "plane_slam/report.hpp"
#include "plane_slam/row_keys.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/verdict.hpp"
#include "sextant/filters/plane_slam_model.hpp"

namespace sextant {
const MethodRows* PlaneSlamRows::find(const std::string& method, const std::string& point) const {
  for (const MethodRows& g : groups)
    if (g.name == method && g.point == point) return &g;
  return nullptr;
}

std::vector<const MethodRows*> PlaneSlamRows::at(const std::string& point) const {
  std::vector<const MethodRows*> out;
  for (const MethodRows& g : groups)
    if (g.point == point && !g.rows.empty()) out.push_back(&g);
  return out;
}

PlaneSlamRows collect_plane_slam_rows(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                                      const std::vector<const RunRow*>& rows) {
  PlaneSlamRows data;
  data.repetitions = config.repetitions;
  for (const auto& axis : config.sweep)
    for (const YAML::Node& v : axis.values) data.points.push_back(v.IsScalar() ? v.Scalar() : YAML::Dump(v));
  if (data.points.empty()) data.points.push_back("");
  for (const std::string& point : data.points)
    for (const MethodConfig& m : config.methods) {
      data.groups.emplace_back();
      data.groups.back().name = m.name;
      data.groups.back().point = point;
    }
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!rows[i]) continue;
    // slam_run_failure's words for a filter that failed on more than half of its steps.
    const bool ended = !rows[i]->ok && rows[i]->error.rfind("the filter failed ", 0) == 0;
    if (!rows[i]->ok && !ended) continue;
    const auto it = runs[i].point.find(kP0ScaleAxis);
    const std::string point = it == runs[i].point.end() ? "" : it->second;
    for (MethodRows& g : data.groups)
      if (g.name == runs[i].method && g.point == point) {
        (ended ? g.ended : g.rows).push_back(rows[i]);
        if (!ended) g.by_point[point_key(runs[i].point, runs[i].repetition)] = rows[i];
      }
  }
  return data;
}

std::vector<Eigen::Vector3d> positions(const std::vector<double>& poses) {
  std::vector<Eigen::Vector3d> out;
  for (std::size_t k = 0; k + 5 < poses.size(); k += 6)
    out.emplace_back(poses[k], poses[k + 1], poses[k + 2]);
  return out;
}

std::vector<double> scan_axis(std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t k = 0; k < n; ++k) x[k] = static_cast<double>(k);
  return x;
}

std::string point_text(const std::string& point) {
  return point.empty() ? "" : "p0_scale = " + point;
}

std::string point_stem(const std::string& point) {
  std::string s = point.empty() ? "" : "_p0_" + point;
  for (char& c : s)
    if (c == '.' || c == '+' || c == '-') c = '_';
  return s;
}

std::string landmark_text(const PlaneSlamParams& params) {
  return params.landmarks == LandmarkSource::kTrue
             ? "the campus' true plane landmarks (observed when a scan has ≥ " +
                   std::to_string(params.min_points) +
                   " points on them) seen from the true pose with N(0, R) noise, true association"
             : "planes extracted from each scan with semantic association and the χ² gate (as the thesis)";
}

std::string common_notes(const ExperimentConfig& config, const PlaneSlamParams& params,
                         const PlaneSlamRows& data) {
  std::size_t scans = 0;
  for (const MethodRows& g : data.groups)
    if (g.first())
      scans = std::max(scans, g.first()->series.count(keys::kErrorM)
                                  ? series_or_empty(*g.first(), keys::kErrorM).size()
                                  : 0);
  std::string s =
      "Landmarks: " + landmark_text(params) + ". Odometry: " +
      (params.odometry == OdometrySource::kResample
           ? "re-drawn for every run from its seed with the campus' odometry model (each repetition an "
             "independent trajectory error)"
           : "the campus' odometry") +
      ". " + std::to_string(scans) + " scans, " + std::to_string(config.repetitions) +
      " repetition(s) per filter; intervals are over the repetitions. Every filter starts at the true "
      "first pose and predicts with the odometry increments (eq. 4.72); the odometry curve is the dead "
      "reckoning of the same increments. NEES of the 6D pose against χ²₆(" +
      format_number(params.nees_probability, 2, "n/a") +
      "); SEIF's pose covariance is its Markov-blanket approximation (conditional, so its NEES is "
      "pessimistic).";
  std::string own;  // issue 27: methods driven by their own odometry model
  for (const MethodConfig& m : config.methods) {
    const PlaneSlamMethod pm = read_plane_slam_method(m.node, config.file);
    if (pm.odometry)
      own +=
          (own.empty() ? "" : ", ") + m.name + " (" + pm.odometry->model +
          (pm.odometry->model == "student_t" ? ", ν = " + format_number(pm.odometry->student_t_dof, 1, "n/a")
                                             : "") +
          ")";
  }
  std::string other;  // methods with their own landmark source (E23's extracted rows)
  for (const MethodConfig& m : config.methods) {
    const PlaneSlamMethod pm = read_plane_slam_method(m.node, config.file);
    if (pm.landmarks && *pm.landmarks != params.landmarks) other += (other.empty() ? "" : ", ") + m.name;
  }
  if (!other.empty()) {
    PlaneSlamParams flipped = params;
    flipped.landmarks =
        params.landmarks == LandmarkSource::kTrue ? LandmarkSource::kExtracted : LandmarkSource::kTrue;
    s += " With their own landmarks instead — " + landmark_text(flipped) +
         "; FastSLAM associates per particle, each particle against its own landmarks at its own pose, and "
         "reports its highest-weight particle's map: " +
         other + ".";
  }
  if (!own.empty())
    s += " Driven instead by their own odometry model, re-drawn for every run from its seed (the odometry "
         "row of that model is the dead reckoning of the first of them): " +
         own + ".";
  return s;
}

std::optional<double> reference_value(const ExperimentConfig& config, const std::string& key,
                                      const std::string& name) {
  return reference_number(child_or_null(config.reference, key), name);
}

bool reference_at_point(const ExperimentConfig& config, const std::string& point) {
  if (point.empty()) return true;
  const YAML::Node& ref = config.reference;
  if (!ref.IsMap() || !ref["p0_scale"].IsDefined()) return false;
  return std::stod(point) == ref["p0_scale"].as<double>();
}

std::optional<Table> plane_slam_sigma_point_table(const ExperimentConfig& config) {
  std::vector<FilterMethodSettings> methods;
  for (const MethodConfig& m : config.methods) {
    const PlaneSlamMethod pm = read_plane_slam_method(m.node, config.file);
    methods.push_back({m.name, pm.filter});
  }
  if (!has_sigma_point_filter(methods)) return std::nullopt;
  return sigma_point_table(methods, std::make_shared<PlaneSlamModel>());
}

ReportFigure error_figure(const PlaneSlamRows& data, const std::string& point, const std::string& series_name,
                          const std::string& odometry_series, const std::string& id,
                          const std::string& y_label, const std::string& caption,
                          const std::map<std::string, std::string>& own_odometry) {
  XYPlot plot;
  plot.title = caption + (point.empty() ? "" : " (" + point_text(point) + ")");
  plot.x_label = "scan";
  plot.y_label = y_label;
  // The dead reckoning once per odometry model (the campus', then each method's own, issue 27).
  std::set<std::string> drawn;
  for (const MethodRows* g : odometry_series.empty() ? std::vector<const MethodRows*>{} : data.at(point)) {
    const auto it = own_odometry.find(g->name);
    const std::string model = it == own_odometry.end() ? "" : it->second;
    if (!drawn.insert(model).second) continue;
    const auto& o = series_or_empty(*g->first(), odometry_series);
    plot.series.push_back({model.empty() ? "odometry" : "odometry (" + model + ")", scan_axis(o.size()), o,
                           PlotSeries::Style::line, model.empty() ? "#888888" : "#bbbbbb"});
  }
  for (const MethodRows* g : data.at(point)) {
    const auto& y = series_or_empty(*g->first(), series_name);
    plot.add_line(g->name, scan_axis(y.size()), y);
  }
  // Filters with near-equal errors (UKF and CKF) overlap: each method its own dashes and markers.
  distinguish_series(plot, drawn.size());
  return {id + point_stem(point),
          caption + (point.empty() ? "" : ", " + point_text(point)) + " (repetition 1)", render_svg(plot)};
}

ReportFigure map_figure(const ExperimentConfig& config, const PlaneSlamParams& params, const RunRow& row,
                        const std::string& method, const std::string& id) {
  (void)config;
  TrajectoryPlot plot;
  plot.title = "Map and trajectories, " + method + " (2σ position ellipses)";
  TrajectorySeries planes{"estimated planes (vertical)", {}, "#9467bd", {}, 10, 2.0};
  const auto& seg = series_or_empty(row, keys::kMapSegments);
  for (std::size_t k = 0; k + 3 < seg.size(); k += 4) {
    planes.positions.emplace_back(seg[k], seg[k + 1], 0.0);
    planes.positions.emplace_back(seg[k + 2], seg[k + 3], 0.0);
    planes.positions.emplace_back(kNaN, kNaN, kNaN);
  }
  if (!planes.positions.empty()) plot.trajectories.push_back(planes);
  plot.trajectories.push_back(  // wide underneath, the estimate dashed on it
      {"ground truth", positions(series_or_empty(row, keys::kTruth)), "#2ca02c", {}, 10, 2.0, "", 3.5});
  plot.trajectories.push_back(
      {"odometry", positions(series_or_empty(row, keys::kOdometry)), "#ff7f0e", {}, 10, 2.0});
  TrajectorySeries est{
      method, positions(series_or_empty(row, keys::kTrajectory)), "#1f77b4", {}, params.ellipse_every, 2.0,
      "8 4"};
  const auto& c = series_or_empty(row, keys::kPositionCovariance);
  for (std::size_t k = 0; k + 5 < c.size(); k += 6) {
    Eigen::Matrix3d P;
    P << c[k], c[k + 1], c[k + 2], c[k + 1], c[k + 3], c[k + 4], c[k + 2], c[k + 4], c[k + 5];
    est.covariances.push_back(P);
  }
  plot.trajectories.push_back(est);
  plot.width = 760;
  plot.height = 600;
  return {id,
          "Top-down map (fig 5.30): " + method + " estimate with 2σ position ellipses every " +
              std::to_string(params.ellipse_every) +
              " scans, ground truth, odometry dead reckoning and the estimated vertical planes (" +
              (seg.empty() ? "none drawn: their extent is only known for true landmarks"
                           : "drawn over their true extent") +
              "); repetition 1",
          render_svg(plot)};
}

std::vector<Claim> beats_odometry_claims(const PlaneSlamRows& data, std::uint64_t seed) {
  std::vector<Claim> out;
  for (const std::string& point : data.points) {
    for (const MethodRows* g : data.at(point)) {
      for (const char* measure : {"max_error_m", "final_error_m"}) {
        const std::string odometry = std::string("odometry_") + measure;
        const Interval d = bootstrap_paired_mean_difference(g->values(measure), g->values(odometry), seed);
        Claim c;
        c.kind = ClaimKind::sanity;
        c.statement = g->name + (point.empty() ? "" : " (" + point_text(point) + ")") + ": " +
                      (measure == std::string("max_error_m") ? "maximum" : "final") +
                      " position error below the odometry's";
        c.verdict = verdict_less(d, 0.0);
        c.evidence = "filter − odometry = " + describe(d, " m") + " over repetitions";
        out.push_back(c);
      }
    }
  }
  return out;
}

}  // namespace sextant
