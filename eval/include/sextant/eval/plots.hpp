#pragma once
// SVG figures written by the project itself (no gnuplot): x–y line/scatter plots, heatmaps with a
// colour bar (success-rate maps) and trajectory plots (top-down / side, optional covariance
// ellipses). Each figure is a plain struct rendered to an SVG string; write_svg writes atomically.
// NaN points are skipped (they break a line into pieces); empty figures still render axes.
#include <cstddef>
#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace sextant {

struct PlotSeries {
  enum class Style { line, markers, line_and_markers };
  enum class Marker { circle, square, triangle, diamond, cross };
  /// `{name, x, y, style, color}` as before; the line style below keeps its defaults.
  PlotSeries(std::string name_ = "", std::vector<double> x_ = {}, std::vector<double> y_ = {},
             Style style_ = Style::line, std::string color_ = "")
      : name(std::move(name_)), x(std::move(x_)), y(std::move(y_)), style(style_), color(std::move(color_)) {}

  std::string name;  ///< legend entry; empty = not in the legend
  std::vector<double> x, y;
  Style style = Style::line;
  std::string color;  ///< CSS colour; empty = the palette's next colour
  std::string dash;   ///< the line's SVG stroke-dasharray, e.g. "7 4" [px]; empty = solid
  Marker marker = Marker::circle;
  double marker_size = 2.5;       ///< marker radius [px]
  std::size_t marker_every = 1;   ///< a marker on every n-th point only (0 counts as 1)
  std::size_t marker_offset = 0;  ///< … from this point on (staggers the markers of overlapping series)
};

struct XYPlot {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
  bool log_x = false;  ///< log10 axis; values ≤ 0 are skipped
  bool log_y = false;
  int width = 640, height = 420;  ///< [px]
  bool legend = true;         ///< legend below the plot area, outside the data (the figure grows by its rows)
  bool equal_aspect = false;  ///< a unit as long on x as on y (the narrower range widens; linear axes)
  /// Optional fixed ranges; NaN = automatic from the data.
  double x_min = std::numeric_limits<double>::quiet_NaN(), x_max = std::numeric_limits<double>::quiet_NaN();
  double y_min = std::numeric_limits<double>::quiet_NaN(), y_max = std::numeric_limits<double>::quiet_NaN();

  /// Convenience: a scatter series.
  XYPlot& add_scatter(const std::string& name, std::vector<double> x, std::vector<double> y);
  XYPlot& add_line(const std::string& name, std::vector<double> x, std::vector<double> y);
};

/// values(r, c) is drawn at column c (x) and row r (y, row 0 at the bottom); NaN = missing (grey).
struct Heatmap {
  std::string title, x_label, y_label, colorbar_label;
  std::vector<std::string> x_ticks;  ///< one per column (may be empty)
  std::vector<std::string> y_ticks;  ///< one per row (may be empty)
  Eigen::MatrixXd values;
  double value_min = 0.0, value_max = 1.0;  ///< colour range (clamped); equal = from the data
  bool annotate = false;                    ///< print each value in its cell
  int annotate_precision = 0;
  int width = 640, height = 480;
};

/// A trajectory in top-down (x, y) or side (x, z) view; equal scale on both axes.
struct TrajectorySeries {
  std::string name;
  std::vector<Eigen::Vector3d> positions;  ///< [m]
  std::string color;
  /// Optional: a 3×3 position covariance per pose [m²]; ellipses drawn every `ellipse_every`.
  std::vector<Eigen::Matrix3d> covariances;
  std::size_t ellipse_every = 10;
  double ellipse_sigma = 2.0;  ///< ellipse radius in standard deviations
  std::string dash = "";       ///< SVG stroke-dasharray [px]; empty = solid
  double width = 1.5;          ///< line width [px]
};

struct TrajectoryPlot {
  enum class View { top_down, side };
  std::string title;
  View view = View::top_down;
  std::vector<TrajectorySeries> trajectories;
  int width = 640, height = 560;
};

/// Gives the series from `first` on distinct line styles, so curves that overlap (e.g. two filters
/// with near-equal errors) stay apart where their colours cannot: the k-th styled series gets the
/// k-th dash pattern (solid, dashed, dotted, dash-dot, …) unless it has its own, and the k-th marker
/// shape on about `markers` of its points, staggered between series. Scatter series get the shape
/// only. Call it before adding reference lines (bounds, thresholds) that should stay plain.
void distinguish_series(XYPlot& plot, std::size_t first = 0, std::size_t markers = 12);

/// The same for trajectories that overlap (an estimate on its ground truth): the first is drawn
/// wide and solid underneath, the k-th after it in the k-th dash pattern, unless they have their own.
void distinguish_trajectories(TrajectoryPlot& plot);

std::string render_svg(const XYPlot& plot);
std::string render_svg(const Heatmap& map);
std::string render_svg(const TrajectoryPlot& plot);

/// Writes an SVG string atomically.
void write_svg(const std::string& svg, const std::filesystem::path& path);

/// Axis ticks: "nice" values (1, 2, 5 × 10^k) covering [lo, hi], about `target` of them.
std::vector<double> nice_ticks(double lo, double hi, int target = 6);
/// The colour map used by heatmaps and sparsity images (viridis-like), t in [0, 1] → "#rrggbb".
std::string colormap(double t);

}  // namespace sextant
