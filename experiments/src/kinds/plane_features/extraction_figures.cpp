// E11's figures (§5.2): fig. 5.21 the cell plane segments of the first scan before merging
// (horizontal ones apart), figs 5.22–5.23 the merged features, fig. 5.24 the correspondence of
// features across the sharp turn under the predicted pose, fig. 5.25 the map of every scan's
// features in the world frame with the robot poses (blue dots). All are top views (x against y).
// The run stores the outlines as NaN-separated x/y series; the report draws them.
#include <cmath>

#include "kit/number_format.hpp"
#include "plane_features/extraction.hpp"
#include "plane_features/row_keys.hpp"
#include "sextant/eval/plots.hpp"
#include "sextant/experiments/run_row.hpp"

namespace sextant {
namespace {

void append(std::vector<double>& to, const std::vector<double>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

/// An outline series `name` of `row` (x from name_x, y from name_y).
PlotSeries outline(const RunRow& row, const std::string& name, const std::string& label,
                   const std::string& colour) {
  return {label, series_or_empty(row, name + "_x"), series_or_empty(row, name + "_y"),
          PlotSeries::Style::line, colour};
}

XYPlot top_view(const std::string& title, const std::string& frame) {
  XYPlot plot{title, "x [m] (" + frame + ")", "y [m]", {}};
  plot.equal_aspect = true;
  plot.height = 560;
  return plot;
}

}  // namespace

void store_hulls(const std::vector<PlaneLandmark>& landmarks, const Eigen::Isometry3d& T,
                 const std::string& name, RunRow& row) {
  std::vector<double>& x = row.series[name + "_x"];
  std::vector<double>& y = row.series[name + "_y"];
  for (const PlaneLandmark& l : landmarks) {
    if (l.hull.empty()) continue;
    for (std::size_t k = 0; k <= l.hull.size(); ++k) {
      const Eigen::Vector3d p = T * l.hull[k % l.hull.size()];
      x.push_back(p.x()), y.push_back(p.y());
    }
    x.push_back(NAN), y.push_back(NAN);
  }
}

std::vector<ReportFigure> extraction_figures(const ExtractionStudyParams& p,
                                             const std::map<std::size_t, const RunRow*>& by_scan) {
  std::vector<ReportFigure> figures;
  const auto find = [&](std::size_t scan) {
    const auto it = by_scan.find(scan);
    return it == by_scan.end() ? nullptr : it->second;
  };
  // Fig. 5.21: cell segments of the first figure scan.
  if (const RunRow* r = p.figure_scans.empty() ? nullptr : find(p.figure_scans.front());
      r && !series_or_empty(*r, "cell_hull_x").empty()) {
    const std::string scan = std::to_string(p.figure_scans.front());
    XYPlot plot = top_view("Fig. 5.21: extracted plane segments of scan " + scan, "sensor frame");
    plot.series.push_back(
        outline(*r, "cell_ground_hull", "horizontal segments (removed after merging)", "#bbbbbb"));
    plot.series.push_back(outline(*r, "cell_hull", "other segments", "#1f77b4"));
    figures.push_back({"cell_segments_scan_" + scan,
                       "Fig. 5.21: convex hulls of the plane segments found in the " +
                           format_number(p.extraction.cell_size, 1) + " m cells of scan " + scan + " (" +
                           format_number(r->value(keys::kCellPlanes), 0) +
                           " segments) before merging; horizontal ones (ground) in grey",
                       render_svg(plot)});
  }
  // Figs 5.22–5.23: merged features.
  for (std::size_t scan : p.figure_scans) {
    const RunRow* r = find(scan);
    if (!r) continue;
    XYPlot plot = top_view("Fig. 5.2" + std::string(scan == p.figure_scans.front() ? "2" : "3") +
                               ": merged plane features of scan " + std::to_string(scan),
                           "sensor frame");
    plot.series.push_back(outline(*r, "hull", "merged features after ground removal", "#1f77b4"));
    figures.push_back({"features_scan_" + std::to_string(scan),
                       "Figs 5.22–5.23: convex hulls of the merged features of scan " + std::to_string(scan) +
                           " after ground removal (" + format_number(r->value(keys::kLandmarks), 0) +
                           " features)",
                       render_svg(plot)});
  }
  // Fig. 5.24: correspondence across the turn under the predicted pose.
  if (const RunRow* r = find(p.turn_scan); r && !series_or_empty(*r, "turn_map_hull_x").empty()) {
    const std::string a = std::to_string(p.turn_scan), b = std::to_string(p.turn_scan + 1);
    XYPlot plot =
        top_view("Fig. 5.24: correspondence of features, scans " + a + " and " + b, "frame of scan " + a);
    plot.series.push_back(outline(*r, "turn_map_hull", "features of scan " + a, "#9ecae1"));
    plot.series.push_back(
        outline(*r, "turn_obs_hull", "features of scan " + b + " at the predicted pose", "#fcae91"));
    plot.series.push_back(outline(*r, "turn_links", "associated pairs (centre to centre)", "#777777"));
    plot.series.push_back(outline(*r, "turn_pair_map", "one corresponded feature: scan " + a, "#08519c"));
    plot.series.push_back(outline(*r, "turn_pair_obs", "… and scan " + b, "#a50f15"));
    figures.push_back({"correspondence_scans_" + a + "_" + b,
                       "Fig. 5.24: the features of scan " + b + " moved into scan " + a +
                           "'s frame by the predicted (odometry) pose across the " +
                           format_number(std::abs(r->value(keys::kTrueYawDeg)), 1) + "° turn, " +
                           format_number(r->value("assoc_odometry_matches"), 0) + " associated pairs (" +
                           format_number(r->value("assoc_odometry_correct"), 0) +
                           " correct); one corresponded pair in dark colours",
                       render_svg(plot)});
  }
  // Fig. 5.25: every scan's features in the world frame and the robot poses.
  XYPlot map = top_view("Fig. 5.25: map of the extracted plane features", "world frame");
  PlotSeries hulls{"features of every scan (true poses)", {}, {}, PlotSeries::Style::line, "#2ca02c"};
  PlotSeries poses{"robot poses", {}, {}, PlotSeries::Style::markers, "#1f4fd6"};
  for (const auto& [scan, r] : by_scan) {
    append(hulls.x, series_or_empty(*r, "world_hull_x")),
        append(hulls.y, series_or_empty(*r, "world_hull_y"));
    if (std::isfinite(r->value(keys::kPoseX)))
      poses.x.push_back(r->value(keys::kPoseX)), poses.y.push_back(r->value(keys::kPoseY));
  }
  if (!poses.x.empty()) {
    map.series = {hulls, poses};
    figures.push_back({"feature_map",
                       "Fig. 5.25: the merged features of scans " + std::to_string(by_scan.begin()->first) +
                           "–" + std::to_string(by_scan.rbegin()->first) +
                           " placed by the ground-truth poses, and the robot poses (blue dots)",
                       render_svg(map)});
  }
  return figures;
}

}  // namespace sextant
