// E20 figures (first repetition): top-down trajectories — truth, chained odometry, pose graph,
// with the loop-closure candidates marked where they were tried (accepted / rejected); the same
// with the injected false closure drawn as a segment and the graphs solved with and without the
// robust loss; and the position error (after alignment) against the scan for every trajectory.
#include <algorithm>
#include <cmath>

#include "kit/number_format.hpp"
#include "kit/row_codec.hpp"
#include "kit/row_keys.hpp"
#include "pose_graph/report.hpp"
#include "pose_graph/row_keys.hpp"
#include "sextant/eval/plots.hpp"

namespace sextant {
namespace {

std::vector<Eigen::Vector3d> positions_of(const RunRow& row, const std::string& name) {
  std::vector<Eigen::Vector3d> out;
  for (const Eigen::Isometry3d& T : series_to_poses(series_or_empty(row, name)))
    out.push_back(T.translation());
  return out;
}

void add_path(XYPlot& plot, const std::string& name, const std::vector<Eigen::Vector3d>& p,
              const std::string& color) {
  PlotSeries s{name, {}, {}, PlotSeries::Style::line, color};
  for (const Eigen::Vector3d& x : p) s.x.push_back(x.x()), s.y.push_back(x.y());
  plot.series.push_back(std::move(s));
}

/// Equal metres per pixel on both axes (XYPlot's plot area is width − 96 by height − 96 px).
void equal_scale(XYPlot& plot) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const PlotSeries& s : plot.series)
    for (std::size_t k = 0; k < std::min(s.x.size(), s.y.size()); ++k)
      if (std::isfinite(s.x[k]) && std::isfinite(s.y[k])) {
        x0 = std::min(x0, s.x[k]), x1 = std::max(x1, s.x[k]);
        y0 = std::min(y0, s.y[k]), y1 = std::max(y1, s.y[k]);
      }
  if (!(x1 > x0) || !(y1 > y0)) return;
  const double w = plot.width - 96.0, h = plot.height - 96.0;
  const double scale = 1.05 * std::max((x1 - x0) / w, (y1 - y0) / h);  // m per px
  const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
  plot.x_min = cx - 0.5 * scale * w, plot.x_max = cx + 0.5 * scale * w;
  plot.y_min = cy - 0.5 * scale * h, plot.y_max = cy + 0.5 * scale * h;
}

ReportFigure closures_figure(const RunRow& row, const std::vector<TrajectoryKind>& kinds) {
  XYPlot plot;
  plot.title = "Trajectories and loop closures (top-down)";
  plot.x_label = "x [m]";
  plot.y_label = "y [m]";
  plot.width = 760;
  plot.height = 600;
  add_path(plot, "ground truth", positions_of(row, keys::kTruth), "#000000");
  add_path(plot, kinds[0].label, positions_of(row, "chained_trajectory"), kinds[0].color);
  const std::vector<Eigen::Vector3d> graph = positions_of(row, "graph_trajectory");
  add_path(plot, kinds[1].label, graph, kinds[1].color);
  PlotSeries accepted{
      "accepted closure (at scan j of the graph)", {}, {}, PlotSeries::Style::markers, "#2a9d3a"};
  PlotSeries rejected{"rejected candidate", {}, {}, PlotSeries::Style::markers, "#c0392b"};
  const std::vector<double>& j = series_or_empty(row, keys::kClosureJ);
  const std::vector<double>& why = series_or_empty(row, keys::kClosureRejection);
  for (std::size_t k = 0; k < j.size() && k < why.size(); ++k) {
    const auto at = static_cast<std::size_t>(j[k]);
    if (at >= graph.size()) continue;
    PlotSeries& s = why[k] == 0.0 ? accepted : rejected;
    s.x.push_back(graph[at].x());
    s.y.push_back(graph[at].y());
  }
  plot.series.push_back(std::move(rejected));
  plot.series.push_back(std::move(accepted));  // on top: a place may be tried again and accepted later
  equal_scale(plot);
  return {
      "trajectories",
      "Top-down trajectories of repetition 1: ground truth, the chained odometry and the pose graph with its "
      "loop closures; markers at the later pose of each candidate (green accepted, red rejected). Equal "
      "scale "
      "on both axes.",
      render_svg(plot)};
}

ReportFigure false_closure_figure(const RunRow& row, const std::vector<TrajectoryKind>& kinds) {
  XYPlot plot;
  plot.title = "A false loop closure, with and without the robust loss";
  plot.x_label = "x [m]";
  plot.y_label = "y [m]";
  plot.width = 760;
  plot.height = 600;
  const std::vector<Eigen::Vector3d> truth = positions_of(row, keys::kTruth);
  add_path(plot, "ground truth", truth, "#000000");
  for (std::size_t k = 2; k < kinds.size(); ++k)
    add_path(plot, kinds[k].label, positions_of(row, kinds[k].prefix + keys::kTrajectory), kinds[k].color);
  PlotSeries link{"false closure (\"same place\"), drawn between the true poses",
                  {},
                  {},
                  PlotSeries::Style::line_and_markers,
                  "#8e44ad"};
  const std::vector<double>&fi = series_or_empty(row, keys::kFalseI),
        &fj = series_or_empty(row, keys::kFalseJ);
  for (std::size_t k = 0; k < fi.size() && k < fj.size(); ++k) {
    const auto i = static_cast<std::size_t>(fi[k]), j = static_cast<std::size_t>(fj[k]);
    if (i >= truth.size() || j >= truth.size()) continue;
    link.x.insert(link.x.end(), {truth[i].x(), truth[j].x(), NAN});
    link.y.insert(link.y.end(), {truth[i].y(), truth[j].y(), NAN});
  }
  plot.series.push_back(std::move(link));
  equal_scale(plot);
  return {
      "false_closure",
      "Repetition 1 with the injected false closure: the graph solved with the robust loss on loop closures "
      "and without it. Equal scale on both axes.",
      render_svg(plot)};
}

ReportFigure error_figure(const MethodRows& odometry, const std::vector<MethodRows>& filters,
                          const std::vector<TrajectoryKind>& kinds) {
  XYPlot plot;
  plot.title = "Position error after SE(3) alignment";
  plot.x_label = "scan";
  plot.y_label = "position error [m]";
  plot.width = 760;
  const RunRow& row = *odometry.rows.front();
  const auto add = [&](const std::string& name, const std::vector<double>& e, const std::string& color) {
    std::vector<double> x(e.size());
    for (std::size_t k = 0; k < x.size(); ++k) x[k] = static_cast<double>(k);
    plot.series.push_back({name, x, e, PlotSeries::Style::line, color});
  };
  for (std::size_t k = 0; k < 2; ++k)
    add(kinds[k].label, series_or_empty(row, kinds[k].prefix + keys::kAteErrors), kinds[k].color);
  for (const MethodRows& f : filters)
    if (!f.rows.empty())
      add(f.name + " (plane SLAM)", series_or_empty(*f.rows.front(), "filter_ate_errors"), "");
  return {"position_error",
          "Position error per scan after each trajectory's own SE(3) Umeyama alignment (the ATE's terms), "
          "repetition 1.",
          render_svg(plot)};
}

}  // namespace

std::vector<ReportFigure> pose_graph_figures(const MethodRows& odometry,
                                             const std::vector<MethodRows>& filters) {
  const std::vector<TrajectoryKind> kinds = graph_trajectories(odometry.name);
  const RunRow& row = *odometry.rows.front();
  return {closures_figure(row, kinds), false_closure_figure(row, kinds),
          error_figure(odometry, filters, kinds)};
}

}  // namespace sextant
