#pragma once
// Grouped bar chart (figs 5.10 and 5.14 of the thesis: mean error per parameter, one bar per
// method in each parameter's group). Bars grow from zero (negative values downwards); the value
// axis always contains zero; a NaN value leaves its slot empty. The legend sits below the plot
// area, outside the data, like XYPlot's.
//
//   BarChart chart;
//   chart.title = "Fig. 5.10 (a): mean translation error";
//   chart.y_label = "mean error [cm]";
//   chart.categories = {"tx", "ty", "tz"};
//   chart.series.push_back({"NDT", {1.2, 0.4, 2.0}, ""});
//   write_svg(render_svg(chart), "fig.svg");
#include <limits>
#include <string>
#include <vector>

namespace sextant {

struct BarSeries {
  std::string name;            ///< legend entry; empty = not in the legend
  std::vector<double> values;  ///< one per category; NaN = no bar
  std::string color;           ///< CSS colour; empty = the palette's colour of the series index
};

struct BarChart {
  std::string title, x_label, y_label;
  std::vector<std::string> categories;  ///< the groups along x, labelled under the axis
  std::vector<BarSeries> series;        ///< one bar per series in every group
  int width = 640, height = 420;        ///< [px]; the legend rows are added below
  /// Optional fixed value range; NaN = from the data (always including zero).
  double y_min = std::numeric_limits<double>::quiet_NaN(), y_max = std::numeric_limits<double>::quiet_NaN();
};

std::string render_svg(const BarChart& chart);

}  // namespace sextant
