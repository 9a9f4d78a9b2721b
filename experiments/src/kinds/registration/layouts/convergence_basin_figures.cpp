#include "registration/layouts/convergence_basin_figures.hpp"

#include <algorithm>
#include <cmath>

#include "kit/row_keys.hpp"
#include "registration/layouts/convergence_basin_analysis.hpp"
#include "registration/report.hpp"
#include "registration/row_keys.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/plots.hpp"
#include "sextant/experiments/run_row.hpp"

namespace sextant {
namespace {

const char* const kColours[3] = {"#1f77b4", "#d62728", "#2ca02c"};
const char* const kTints[3] = {"#9ecae1", "#f4a6a6", "#a1d99b"};
// Methods drawn in one figure also differ in dash pattern and marker (their curves may coincide).
const char* const kDashes[3] = {"", "7 4", "2 3"};
const PlotSeries::Marker kMarkers[3] = {PlotSeries::Marker::circle, PlotSeries::Marker::square,
                                        PlotSeries::Marker::triangle};

PointCloud cloud_of(const std::vector<double>& xyz) {
  PointCloud cloud;
  cloud.reserve(xyz.size() / 3);
  for (std::size_t k = 0; k + 3 <= xyz.size(); k += 3)
    cloud.push_back(Eigen::Vector3f(static_cast<float>(xyz[k]), static_cast<float>(xyz[k + 1]),
                                    static_cast<float>(xyz[k + 2])));
  return cloud;
}

/// Iterate k's six parameters (k = 0: the initial guess) in m and deg.
std::vector<Vector6d> iterates(const RunRow& row) {
  std::vector<Vector6d> out{to_pose6(series_to_isometry(series_or_empty(row, keys::kInitial))).vector()};
  const std::vector<double>& xi = series_or_empty(row, keys::kTraceXi);
  for (std::size_t k = 0; k + 6 <= xi.size(); k += 6) {
    Vector6d v;
    for (int j = 0; j < 6; ++j) v[j] = xi[k + static_cast<std::size_t>(j)];
    out.push_back(v);
  }
  return out;
}

}  // namespace

ReportFigure cloud_figure(const std::string& id, const std::string& caption, const std::string& title,
                          const RunRow& snapshot, const Eigen::Isometry3d& T) {
  const std::vector<double>& ref = series_or_empty(snapshot, keys::kSnapshotReference);
  const std::vector<double>& in = series_or_empty(snapshot, keys::kSnapshotInput);
  XYPlot plot;
  plot.title = title;
  plot.x_label = "x [m]";
  plot.y_label = "y [m]";
  plot.width = plot.height = 620;
  std::vector<double> rx, ry, ix, iy;
  for (std::size_t k = 0; k + 3 <= ref.size(); k += 3) {
    rx.push_back(ref[k]);
    ry.push_back(ref[k + 1]);
  }
  for (std::size_t k = 0; k + 3 <= in.size(); k += 3) {
    const Eigen::Vector3d p = T * Eigen::Vector3d(in[k], in[k + 1], in[k + 2]);
    ix.push_back(p.x());
    iy.push_back(p.y());
  }
  // Equal scale: one span for both axes around the reference.
  if (!rx.empty()) {
    const auto [x0, x1] = std::minmax_element(rx.begin(), rx.end());
    const auto [y0, y1] = std::minmax_element(ry.begin(), ry.end());
    const double half = 0.55 * std::max(*x1 - *x0, *y1 - *y0), cx = 0.5 * (*x0 + *x1), cy = 0.5 * (*y0 + *y1);
    plot.x_min = cx - half;
    plot.x_max = cx + half;
    plot.y_min = cy - half;
    plot.y_max = cy + half;
  }
  plot.add_scatter("reference", std::move(rx), std::move(ry));
  plot.series.back().color = "#1f77b4";
  plot.add_scatter("input", std::move(ix), std::move(iy));
  plot.series.back().color = "#d62728";
  return {id, caption, render_svg(plot)};
}

ReportScene cloud_scene(const std::string& id, const std::string& caption, const std::string& title,
                        const RunRow& snapshot,
                        const std::vector<std::pair<std::string, const RunRow*>>& after) {
  ReportScene scene{id, caption, {}};
  CloudView& view = scene.view;
  view.title = title;
  view.caption =
      "The reference, and the displaced input placed by the identity guess, by each method's "
      "estimate and by the ground truth (buttons or keys 1–" +
      std::to_string(after.size() + 2) +
      "); the clouds as the run stored them (about snapshot_points per cloud, above the ground).";
  std::vector<Eigen::Isometry3d> poses{Eigen::Isometry3d::Identity()};
  view.states.push_back("before: identity guess");
  for (const auto& [name, row] : after) {
    poses.push_back(series_to_isometry(series_or_empty(*row, keys::kEstimate)));
    view.states.push_back("after " + name + " (" +
                          format_number(row->value(keys::kTranslationCm) / 100.0, 2) + " m, " +
                          format_number(row->value(keys::kRotationDeg), 1) + "° off)");
  }
  poses.push_back(series_to_isometry(series_or_empty(snapshot, keys::kGroundTruth)));
  view.states.push_back("ground truth");
  view.clouds.push_back(
      {"reference", cloud_of(series_or_empty(snapshot, keys::kSnapshotReference)), "", {}, {}});
  view.clouds.push_back(
      {"input", cloud_of(series_or_empty(snapshot, keys::kSnapshotInput)), "", std::move(poses), {}});
  return scene;
}

std::vector<ReportFigure> parameter_figures(const std::string& method, const std::string& figure,
                                            const RunRow& row) {
  const std::vector<Vector6d> steps = iterates(row);
  const Vector6d truth = to_pose6(series_to_isometry(series_or_empty(row, keys::kGroundTruth))).vector();
  static const char* const kNames[6] = {"tx", "ty", "tz", "α", "β", "γ"};
  std::vector<ReportFigure> out;
  for (int part = 0; part < 2; ++part) {
    const double scale = part == 0 ? 1.0 : kDegPerRad;
    XYPlot plot;
    plot.title = "Parameters vs iteration, " + method + (part == 0 ? " (translation)" : " (rotation)");
    plot.x_label = "iteration (0 = initial guess)";
    plot.y_label = part == 0 ? "translation [m]" : "rotation [deg]";
    for (int j = 0; j < 3; ++j) {
      const int p = 3 * part + j;
      std::vector<double> x, y;
      for (std::size_t k = 0; k < steps.size(); ++k) {
        x.push_back(static_cast<double>(k));
        y.push_back(scale * steps[k][p]);
      }
      const double last = x.empty() ? 1.0 : std::max(1.0, x.back());
      plot.add_line(std::string(kNames[p]) + " true", {0.0, last}, {scale * truth[p], scale * truth[p]});
      plot.series.back().color = kTints[j];
      plot.series.back().dash = "6 4";
      plot.add_line(kNames[p], std::move(x), std::move(y));
      plot.series.back().color = kColours[j];
      plot.series.back().style = PlotSeries::Style::line_and_markers;
    }
    out.push_back({"parameters_" + method + (part == 0 ? "_translation" : "_rotation"),
                   "Parameter update of " + method + " at the snapshot offset (" + figure + ", " +
                       (part == 0 ? "translations" : "rotations") + "; light lines: the true offset)",
                   render_svg(plot)});
  }
  return out;
}

ReportFigure score_figure(const std::string& id, const std::string& caption, const std::string& title,
                          const std::vector<std::pair<std::string, const RunRow*>>& rows, bool per_layer) {
  XYPlot plot;
  plot.title = title;
  plot.x_label = "iteration";
  plot.y_label = per_layer ? "score normalised per layer: (s − s_last) / (s_first − s_last)" : "score";
  for (std::size_t m = 0; m < rows.size(); ++m) {
    const std::vector<double>& score = series_or_empty(*rows[m].second, keys::kScore);
    const std::vector<double>& layer = series_or_empty(*rows[m].second, keys::kLayer);
    const std::vector<double> y = per_layer ? normalise_per_layer(score, layer) : score;
    // One line per layer (the first named), all in the method's colour.
    std::size_t begin = 0;
    while (begin < y.size()) {
      std::size_t end = begin + 1;
      while (per_layer && end < y.size() && end < layer.size() && layer[end] == layer[begin]) ++end;
      if (!per_layer) end = y.size();
      std::vector<double> xs, ys;
      for (std::size_t k = begin; k < end; ++k) {
        xs.push_back(static_cast<double>(k + 1));
        ys.push_back(y[k]);
      }
      plot.add_line(begin == 0 ? rows[m].first : "", std::move(xs), std::move(ys));
      plot.series.back().color = kColours[m % 3];
      plot.series.back().style = PlotSeries::Style::line_and_markers;
      plot.series.back().dash = kDashes[m % 3];
      plot.series.back().marker = kMarkers[m % 3];
      begin = end;
    }
  }
  return {id, caption, render_svg(plot)};
}

ReportFigure error_figure(const std::string& id, const std::string& caption, const std::string& title,
                          const std::vector<std::pair<std::string, const RunRow*>>& rows) {
  XYPlot plot;
  plot.title = title;
  plot.x_label = "iteration (0 = initial guess)";
  plot.y_label = "translation error ‖t(E)‖ [m] (log)";
  plot.log_y = true;
  for (std::size_t m = 0; m < rows.size(); ++m) {
    const auto errors = iterate_errors(*rows[m].second);
    std::vector<double> x, y;
    for (std::size_t k = 0; k < errors.size(); ++k) {
      x.push_back(static_cast<double>(k));
      y.push_back(std::max(errors[k].first, 1e-4));
    }
    plot.add_line(rows[m].first, std::move(x), std::move(y));
    plot.series.back().color = kColours[m % 3];
    plot.series.back().style = PlotSeries::Style::line_and_markers;
    plot.series.back().dash = kDashes[m % 3];
    plot.series.back().marker = kMarkers[m % 3];
  }
  return {id, caption, render_svg(plot)};
}

ReportFigure heatmap_figure(const std::string& id, const std::string& caption, const std::string& title,
                            const std::string& x_label, const std::string& y_label, const std::string& bar,
                            const std::vector<std::string>& x_ticks, const std::vector<std::string>& y_ticks,
                            const Eigen::MatrixXd& values, double max_value, int precision) {
  Heatmap map;
  map.title = title;
  map.x_label = x_label;
  map.y_label = y_label;
  map.colorbar_label = bar;
  map.x_ticks = x_ticks;
  map.y_ticks = y_ticks;
  map.values = values;
  map.value_min = 0.0;
  map.value_max = max_value > 0 ? max_value : 1.0;
  map.annotate = true;
  map.annotate_precision = precision;
  // Wide enough that tick labels of ~10 characters do not run into each other.
  map.width = std::max(640, 260 + 90 * static_cast<int>(values.cols()));
  return {id, caption, render_svg(map)};
}

}  // namespace sextant
