// Layout (§5.2.1.4, figs 5.39–5.46): measurement- and motion-update times per scan of SEIF and
// EKF and their growth with the map (least-squares slope of time against map size with a
// bootstrap interval, sequence_analysis.hpp), SEIF's error, and the information-matrix images
// (block pattern of Ω with and without sparsification, and for the whole map).
#include <algorithm>
#include <cmath>
#include <map>

#include "plane_slam/report.hpp"
#include "plane_slam/row_keys.hpp"
#include "sextant/eval/sequence_analysis.hpp"
#include "sextant/eval/sparsity.hpp"
#include "sextant/eval/statistics.hpp"
#include "sextant/eval/verdict.hpp"

namespace sextant {
TimeGrowth time_growth(const MethodRows& g, const std::string& time, std::uint64_t seed) {
  std::vector<double> x, y;
  for (const RunRow* r : g.rows) {
    const auto& t = series_or_empty(*r, time);
    const auto& m = series_or_empty(*r, keys::kMapSize);
    for (std::size_t k = 1; k < std::min(t.size(), m.size()); ++k) {
      x.push_back(m[k]);
      y.push_back(t[k]);
    }
  }
  TimeGrowth out;
  out.slope = bootstrap_slope(x, y, seed);
  if (x.empty()) return out;
  std::vector<double> sorted = y;
  std::sort(sorted.begin(), sorted.end());
  out.median_ms = sorted[sorted.size() / 2];
  out.map_lo = *std::min_element(x.begin(), x.end());
  out.map_hi = *std::max_element(x.begin(), x.end());
  const double scale = out.median_ms > 0 ? (out.map_hi - out.map_lo) / out.median_ms : NAN;
  out.growth = {out.slope.estimate * scale, out.slope.lo * scale, out.slope.hi * scale, out.slope.confidence,
                out.slope.n};
  return out;
}

ReportFigure time_figure(const PlaneSlamRows& data, const std::string& time, const std::string& id,
                         const std::string& what, bool against_map) {
  XYPlot plot;
  plot.title = what + (against_map ? " against the map size" : " per scan");
  plot.x_label = against_map ? "landmarks in the map" : "scan";
  plot.y_label = what + " [ms]";
  plot.log_y = true;
  for (const MethodRows* g : data.at(data.points.front())) {
    const RunRow& r = *g->first();
    std::vector<double> y = series_or_empty(r, time);
    if (!y.empty()) y.front() = NAN;  // scan 0: no motion update; its augmentations are not comparable
    if (against_map)
      plot.add_scatter(g->name, series_or_empty(r, keys::kMapSize), y);
    else
      plot.add_line(g->name, scan_axis(y.size()), y);
  }
  distinguish_series(plot);
  return {
      id,
      what + (against_map ? " against the number of landmarks" : " per scan") + " (repetition 1; log scale)",
      render_svg(plot)};
}

std::vector<ReportFigure> information_figures(const PlaneSlamRows& data) {
  std::vector<ReportFigure> out;
  for (const MethodRows* g : data.at(data.points.front())) {
    const RunRow& r = *g->first();
    for (int i = 0;; ++i) {
      const std::string key = "information_" + std::to_string(i);
      if (!r.series.count(key)) break;
      const std::size_t landmarks = static_cast<std::size_t>(r.value(key + "_landmarks"));
      const std::size_t dim = 6 + 4 * landmarks, scan = static_cast<std::size_t>(r.value(key + "_scan"));
      const auto offset = [](std::size_t v) { return v == 0 ? std::size_t{0} : 6 + 4 * (v - 1); };
      const auto size = [](std::size_t v) { return v == 0 ? std::size_t{6} : std::size_t{4}; };
      std::vector<std::pair<std::size_t, std::size_t>> entries;
      const auto block = [&](std::size_t a, std::size_t b) {
        for (std::size_t p = 0; p < size(a); ++p)
          for (std::size_t q = 0; q < size(b); ++q) entries.emplace_back(offset(a) + p, offset(b) + q);
      };
      for (std::size_t v = 0; v <= landmarks; ++v) block(v, v);
      const auto& links = series_or_empty(r, key);
      for (std::size_t k = 0; k + 1 < links.size(); k += 2) {
        const auto a = static_cast<std::size_t>(links[k]), b = static_cast<std::size_t>(links[k + 1]);
        block(a, b);
        block(b, a);
      }
      const SparsityGrid grid = sparsity_grid(dim, dim, entries, 300);
      const std::string what = g->name == "eif" ? "without sparsification (EIF)" : "of " + g->name;
      const std::string title = "Information matrix " + what + ": " + std::to_string(landmarks) +
                                " landmarks (" + std::to_string(dim) + "×" + std::to_string(dim) +
                                "), after scan " + std::to_string(scan);
      out.push_back(
          {"information_" + g->name + "_" + std::to_string(landmarks),
           title + "; " + std::to_string(links.size() / 2) +
               " linked variable pairs (structural non-zero blocks), " +
               format_number(100.0 * static_cast<double>(grid.nonzeros) / double(dim * dim), 1, "n/a") +
               " % of the entries",
           render_sparsity_svg(grid, title)});
    }
  }
  return out;
}

namespace {

Claim growth_claim(const std::string& method, const std::string& what, const TimeGrowth& g, bool flat) {
  Claim c;
  c.statement =
      method + "'s " + what + " time " +
      (flat ? "stays flat as the map grows (changes by < " + format_number(100 * kFlatGrowth, 0, "n/a") +
                  " % of its median across the map's range)"
            : "grows with the map (by > " + format_number(100 * kFlatGrowth, 0, "n/a") +
                  " % of its median across the map's range)");
  c.verdict =
      flat ? verdict_in_band(g.growth, -kFlatGrowth, kFlatGrowth) : verdict_greater(g.growth, kFlatGrowth);
  c.evidence = "slope " + describe(g.slope, " ms/landmark", 4) + "; growth over " +
               format_number(g.map_lo, 0, "n/a") + "–" + format_number(g.map_hi, 0, "n/a") + " landmarks " +
               describe(g.growth, "", 2) + " × median " + format_number(g.median_ms, 3, "n/a") +
               " ms (n = scans pooled over repetitions)";
  return c;
}

}  // namespace

ReportSection seif_report(const ExperimentConfig& config, const PlaneSlamParams& params,
                          const PlaneSlamRows& data) {
  ReportSection section;
  section.notes =
      common_notes(config, params, data) +
      " Times are our C++ wall times per scan (measurement update = update + augmentation; motion "
      "update = prediction), measured while other runs share the machine; the thesis' are MATLAB's. "
      "The information images show Ω's structural block pattern (a block is drawn when the filter "
      "links the two variables), downsampled to at most 300×300 cells.";
  Table t;
  t.caption = "Update times and their growth with the map (ours | thesis)";
  t.label = "update_times";
  t.note =
      "slopes by least squares of time against map size, 95 % bootstrap intervals over the scans; median "
      "over "
      "scans and repetitions; map size and final error (3D position error after the last scan [m]): medians "
      "over repetitions.";
  t.add_column("method")
      .add_number_column("measurement ms (median)", 3)
      .add_number_column("measurement slope ms/landmark", 4)
      .add_number_column("motion ms (median)", 3)
      .add_number_column("motion slope ms/landmark", 4)
      .add_compared_column("map size", 0)
      .add_compared_column("final error m", 2);
  std::uint64_t seed = config.seed * 7919u;
  std::map<std::string, std::pair<TimeGrowth, TimeGrowth>> growth;
  for (const MethodRows* g : data.at(data.points.front())) {
    const TimeGrowth m = time_growth(*g, keys::kMeasurementMs, ++seed),
                     p = time_growth(*g, keys::kMotionMs, ++seed);
    growth[g->name] = {m, p};
    t.add_row({Cell::text(g->name), number_or_missing(m.median_ms), number_or_missing(m.slope.estimate),
               number_or_missing(p.median_ms), number_or_missing(p.slope.estimate),
               number_or_missing(median_of(g->values(keys::kMapSize))),
               number_or_missing(reference_value(config, "map_size", g->name)),
               number_or_missing(median_of(g->values("final_error_m"))),
               number_or_missing(reference_value(config, "final_error_m", g->name))});
  }
  section.tables.push_back(t);
  section.figures.push_back(
      time_figure(data, keys::kMeasurementMs, "measurement_time", "Measurement update", false));
  section.figures.push_back(time_figure(data, keys::kMotionMs, "motion_time", "Motion update", false));
  section.figures.push_back(
      time_figure(data, keys::kMeasurementMs, "measurement_time_vs_map", "Measurement update", true));
  section.figures.push_back(time_figure(data, keys::kMotionMs, "motion_time_vs_map", "Motion update", true));
  section.figures.push_back(error_figure(data, data.points.front(), keys::kErrorM, keys::kOdometryErrorM,
                                         "error_vs_scan", "position error norm [m]",
                                         "Position error norm per scan"));
  for (ReportFigure& f : information_figures(data)) section.figures.push_back(std::move(f));
  if (const MethodRows* seif = data.find("seif", data.points.front()); seif && seif->first())
    section.figures.push_back(map_figure(config, params, *seif->first(), "seif", "map_seif"));

  for (const auto& [method, g] : growth) {
    if (method == "eif") continue;  // stops early, for the image only
    const bool flat = method == "seif";
    if (!flat && method != "ekf") continue;
    section.claims.push_back(growth_claim(method, "measurement-update", g.first, flat));
    section.claims.push_back(growth_claim(method, "motion-update", g.second, flat));
  }
  section.claims.push_back({"The EKF's update time drops at loop closures when associated planes are merged",
                            Verdict::not_comparable,
                            params.landmarks == LandmarkSource::kTrue
                                ? "with true landmarks and true association every plane enters the map once: "
                                  "there is nothing to merge"
                                : "the filters here never merge map landmarks (PlaneSlam merges semantics "
                                  "only), so the map never shrinks",
                            ClaimKind::thesis});
  for (Claim& c : declared_claims(config, params, data)) section.claims.push_back(c);
  for (Claim& c : beats_odometry_claims(data, config.seed)) section.claims.push_back(c);
  return section;
}

}  // namespace sextant
