// E15 layout: fig. 5.35 (average position and orientation error norms against time over the
// Monte Carlo runs), fig. 5.36 (the map and the estimated paths of one run), the error table and
// the claims: RSPKF below UKF (paired differences per repetition, bootstrap interval), RSPKF
// without systematic error (mean signed error in the vehicle frame within a stated band).
#include <cmath>
#include <map>

#include "kit/filter_parameters.hpp"
#include "kit/number_format.hpp"
#include "kit/row_groups.hpp"
#include "kit/row_keys.hpp"
#include "sextant/eval/plots.hpp"
#include "sextant/eval/verdict.hpp"
#include "sextant/experiments/run_row.hpp"
#include "simulation/monte_carlo_report.hpp"
#include "simulation/row_keys.hpp"

namespace sextant {
namespace {

/// The paired values of two methods (repetitions both have), a[i] and b[i].
void paired(const MethodRows& a, const MethodRows& b, const std::string& name, std::vector<double>* va,
            std::vector<double>* vb) {
  const PairedRows p = pair_up_in_order(a, b);
  *va = row_values(p.a, name);
  *vb = row_values(p.b, name);
}

/// Mean over the repetitions of a per-time series (all runs share the time grid: the true path
/// does not depend on the noise).
std::pair<std::vector<double>, std::vector<double>> mean_curve(const MethodRows& m, const std::string& name) {
  std::vector<double> t, sum, count;
  for (const RunRow* row : m.rows) {
    const auto& rt = series_or_empty(*row, "t");
    const auto& v = series_or_empty(*row, name);
    if (rt.size() > t.size()) t = rt, sum.resize(t.size(), 0.0), count.resize(t.size(), 0.0);
    for (std::size_t k = 0; k < std::min(rt.size(), v.size()); ++k) sum[k] += v[k], count[k] += 1;
  }
  for (std::size_t k = 0; k < t.size(); ++k) sum[k] = count[k] > 0 ? sum[k] / count[k] : NAN;
  return {t, sum};
}

}  // namespace

ReportSection monte_carlo_report(const ExperimentConfig& config, const MonteCarloParams& p,
                                 const RangeBearingWorld& world, const std::vector<RunSpec>& runs,
                                 const std::vector<const RunRow*>& rows) {
  std::map<std::string, MethodRows> methods;
  for (MethodRows& m : group_by_method(config, runs, rows))
    if (!m.rows.empty()) methods[m.name] = std::move(m);

  ReportSection section;
  section.notes =
      std::to_string(p.landmarks) + " point landmarks near a " + format_number(p.side, 0) +
      " m square loop; V = " + format_number(p.sim.speed, 1) + " m/s, dt = " + format_number(p.sim.dt, 2) +
      " s, an observation every " + format_number(p.sim.observe_every, 1) + " s (range ≤ " +
      format_number(p.sim.max_range, 0) + " m); noise σ_V = " + format_number(p.sim.sigma_speed, 2) +
      " m/s, σ_γ = " + format_number(p.sim.sigma_steer / 0.017453292519943295, 2) +
      "°, σ_r = " + format_number(p.sim.sigma_range, 2) +
      " m, σ_b = " + format_number(p.sim.sigma_bearing / 0.017453292519943295, 2) +
      "°; known association. Deviations from the thesis: the world and the waypoints are ours (the thesis "
      "does not give them); we read Q = R = diag(1, π/180) as the σ's of the stated noise, so the filters "
      "use "
      "Q = diag(σ_V², σ_γ²), R = diag(σ_r², σ_b²); errors are averaged over every control step of a run.";

  std::vector<FilterMethodSettings> filters;
  for (const auto& m : config.methods)
    filters.push_back({m.name, read_range_bearing_filter(m.node, config.file)});
  section.tables.push_back(sigma_point_table(filters, std::make_shared<RangeBearingModel>(p.sim.model())));

  // Fig. 5.35: average position / orientation error norms against time.
  XYPlot position{
      "Fig. 5.35: average position error norm over the runs", "time [s]", "position error [m]", {}};
  XYPlot heading{"Average orientation error norm over the runs", "time [s]", "heading error [deg]", {}};
  for (const auto& m : config.methods) {
    if (!methods.count(m.name)) continue;
    auto [t, e] = mean_curve(methods[m.name], keys::kPositionErrorM);
    position.add_line(m.name, t, e);
    auto [th, h] = mean_curve(methods[m.name], keys::kHeadingErrorDeg);
    heading.add_line(m.name, th, h);
  }
  // The UKF's and the RSPKF's curves nearly coincide: dash patterns and markers keep both visible.
  distinguish_series(position);
  distinguish_series(heading);
  section.figures.push_back({"average_position_error", "Fig. 5.35: average position error norm against time",
                             render_svg(position)});
  section.figures.push_back(
      {"average_heading_error", "Average orientation error norm against time", render_svg(heading)});

  // Fig. 5.36: the feature map and the estimated paths (repetition 0).
  XYPlot map{"Fig. 5.36: landmarks and paths, repetition 0", "x [m]", "y [m]", {}};
  std::vector<double> lx, ly;
  for (const auto& l : world.landmarks) lx.push_back(l.x()), ly.push_back(l.y());
  map.series.push_back({"true landmarks", lx, ly, PlotSeries::Style::markers, "#000000"});
  bool truth_drawn = false;
  std::size_t drawn = 0;  // methods drawn so far: each its own dash pattern and landmark marker
  for (const auto& m : config.methods) {
    const auto found = methods.find(m.name);
    if (found == methods.end() || found->second.rows.front()->repetition != 0) continue;
    const RunRow& r = *found->second.rows.front();
    if (!truth_drawn) {
      map.series.push_back({"true path", series_or_empty(r, keys::kTruthX), series_or_empty(r, keys::kTruthY),
                            PlotSeries::Style::line, "#000000"});
      truth_drawn = true;
    }
    static const char* const kDashes[] = {"", "7 4", "2 3"};
    static const PlotSeries::Marker kShapes[] = {PlotSeries::Marker::square, PlotSeries::Marker::triangle,
                                                 PlotSeries::Marker::diamond};
    map.add_line(m.name + " path", series_or_empty(r, keys::kEstX), series_or_empty(r, keys::kEstY));
    map.series.back().dash = kDashes[drawn % 3];
    map.series.push_back({m.name + " landmarks", series_or_empty(r, keys::kMapX),
                          series_or_empty(r, keys::kMapY), PlotSeries::Style::markers, ""});
    map.series.back().marker = kShapes[drawn % 3];
    map.series.back().marker_size = 3.5;
    ++drawn;
  }
  section.figures.push_back(
      {"map_and_paths",
       "Fig. 5.36: true and estimated landmarks, true and estimated paths (repetition 0; where the UKF's "
       "and the RSPKF's estimates coincide, their dash patterns and landmark markers tell them apart)",
       render_svg(map)});

  Table table;
  table.caption = "E15: errors over the Monte Carlo runs, mean with its 95 % interval";
  table.label = "monte_carlo_errors";
  table.note =
      "signed errors in the vehicle frame of the true pose (along track +forward, cross track +left)";
  table.add_column("method").add_number_column("runs", 0);
  for (const char* h : {"position error [m]", "heading error [deg]", "along track [m]", "cross track [m]",
                        "signed heading [deg]"})
    table.add_number_column("mean", 3, h)
        .add_number_column("95 % lo", 3, h)
        .add_number_column("95 % hi", 3, h);
  table.add_number_column("failed steps", 0);
  const auto add_row = [&](const std::string& name, const MethodRows& m, bool dead_reckoning) {
    std::vector<Cell> cells{Cell::text(name), Cell::number(static_cast<double>(m.rows.size()))};
    for (const char* v : {keys::kMeanPositionErrorM, keys::kMeanHeadingErrorDeg, keys::kMeanAlongTrackM,
                          keys::kMeanCrossTrackM, keys::kMeanSignedHeadingDeg}) {
      const bool shown = !dead_reckoning || std::string(v) == keys::kMeanPositionErrorM;
      const Interval i = mean_interval(m.values(dead_reckoning && shown ? keys::kDeadReckoningErrorM : v));
      for (double x : {i.estimate, i.lo, i.hi})
        cells.push_back(shown ? number_or_missing(x) : Cell::missing());
    }
    double failed = 0;
    for (double f : m.values(keys::kFailedSteps)) failed += f;
    cells.push_back(dead_reckoning ? Cell::missing() : Cell::number(failed));
    table.add_row(std::move(cells));
  };
  for (const auto& m : config.methods)
    if (methods.count(m.name)) add_row(m.name, methods[m.name], false);
  if (methods.count(p.baseline)) add_row("dead reckoning", methods[p.baseline], true);
  section.tables.push_back(table);

  // Claims: paired per repetition.
  const MethodRows& base = methods[p.baseline];
  const MethodRows& prop = methods[p.proposed];
  Table diff_table;
  diff_table.caption = "E15: paired difference " + p.proposed + " − " + p.baseline + " per repetition";
  diff_table.label = "monte_carlo_paired_difference";
  diff_table.add_column("quantity")
      .add_number_column("mean difference", 3)
      .add_number_column("95 % lo", 3)
      .add_number_column("95 % hi", 3)
      .add_number_column("pairs", 0);
  const auto difference = [&](const std::string& value, std::uint64_t salt) {
    std::vector<double> a, b;
    paired(prop, base, value, &a, &b);
    const Interval d = bootstrap_paired_mean_difference(a, b, config.seed + salt);
    diff_table.add_row({Cell::text(value), number_or_missing(d.estimate), number_or_missing(d.lo),
                        number_or_missing(d.hi), Cell::number(static_cast<double>(d.n))});
    return d;
  };
  const Interval dp = difference(keys::kMeanPositionErrorM, 1);
  const Interval dh = difference(keys::kMeanHeadingErrorDeg, 2);
  (void)difference(keys::kFinalPositionErrorM, 3);
  section.tables.push_back(diff_table);
  section.claims.push_back({"The RSPKF's average position error norm is below the UKF's (fig. 5.35)",
                            verdict_less(dp, 0.0),
                            p.proposed + " − " + p.baseline + " per repetition " + describe(dp, " m", 3)});
  section.claims.push_back({"The RSPKF's average orientation error norm is below the UKF's",
                            verdict_less(dh, 0.0),
                            p.proposed + " − " + p.baseline + " per repetition " + describe(dh, "°", 3)});

  const Interval along = mean_interval(prop.values(keys::kMeanAlongTrackM));
  const Interval cross = mean_interval(prop.values(keys::kMeanCrossTrackM));
  const Interval sh = mean_interval(prop.values(keys::kMeanSignedHeadingDeg));
  const double bp = p.bias_band_position, bh = p.bias_band_heading_deg;
  section.claims.push_back({"The RSPKF has no systematic error: its mean signed error is zero (within ±" +
                                format_number(bp, 2) + " m, ±" + format_number(bh, 2) + "°)",
                            verdict_all({verdict_in_band(along, -bp, bp), verdict_in_band(cross, -bp, bp),
                                         verdict_in_band(sh, -bh, bh)}),
                            "along track " + describe(along, " m", 3) + ", cross track " +
                                describe(cross, " m", 3) + ", heading " + describe(sh, "°", 3)});
  for (const auto& [name, m] : methods) {
    std::vector<double> est = m.values(keys::kMeanPositionErrorM), odo = m.values(keys::kDeadReckoningErrorM);
    const Interval d = bootstrap_paired_mean_difference(est, odo, config.seed + 7);
    section.claims.push_back({name + " is more accurate than dead reckoning of the same controls",
                              verdict_less(d, 0.0), "error − dead-reckoning error " + describe(d, " m", 3),
                              ClaimKind::sanity});
  }
  return section;
}

}  // namespace sextant
