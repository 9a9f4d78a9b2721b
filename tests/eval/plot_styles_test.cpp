// Line styles of XYPlot series: a dash pattern and marker shapes per series (distinguish_series),
// drawn on the lines and on the legend's samples, so overlapping curves stay distinguishable.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "sextant/eval/plots.hpp"
#include "xml_check.hpp"

namespace sextant {
namespace {

using sextant::testing::occurrences;

/// The dash attribute of every <polyline> (empty when solid), in drawing order.
std::vector<std::string> polyline_dashes(const std::string& svg) {
  std::vector<std::string> out;
  for (std::size_t p = svg.find("<polyline"); p != std::string::npos; p = svg.find("<polyline", p + 1)) {
    const std::string element = svg.substr(p, svg.find("/>", p) - p);
    const std::size_t d = element.find("stroke-dasharray=\"");
    out.push_back(d == std::string::npos ? "" : element.substr(d + 18, element.find('"', d + 18) - d - 18));
  }
  return out;
}

/// Two curves that coincide, like E13/E19's UKF and CKF.
XYPlot overlapping() {
  XYPlot plot;
  std::vector<double> x, y;
  for (int i = 0; i < 60; ++i) x.push_back(i), y.push_back(0.1 * i);
  plot.add_line("ukf", x, y).add_line("ckf", x, y).add_line("ekf", x, y);
  return plot;
}

TEST(PlotStyles, OverlappingSeriesGetDistinctDashesAndMarkers) {
  XYPlot plain = overlapping();
  const std::string before = render_svg(plain);
  // Without styles every line is solid and there are no markers: the curves cannot be told apart.
  EXPECT_EQ(polyline_dashes(before), (std::vector<std::string>{"", "", ""}));

  XYPlot plot = overlapping();
  distinguish_series(plot);
  std::set<std::string> dashes;
  std::set<PlotSeries::Marker> markers;
  for (const PlotSeries& s : plot.series) {
    dashes.insert(s.dash);
    markers.insert(s.marker);
    EXPECT_EQ(s.style, PlotSeries::Style::line_and_markers);
    EXPECT_EQ(s.marker_every, 5u);  // about 12 markers on 60 points
  }
  EXPECT_EQ(dashes.size(), 3u);
  EXPECT_EQ(markers.size(), 3u);
  // Markers are staggered: the series' first markers sit on different points.
  EXPECT_NE(plot.series[0].marker_offset, plot.series[1].marker_offset);
  EXPECT_NE(plot.series[1].marker_offset, plot.series[2].marker_offset);

  const std::string svg = render_svg(plot);
  EXPECT_TRUE(sextant::testing::check_xml(svg).ok) << sextant::testing::check_xml(svg).error;
  const std::vector<std::string> drawn = polyline_dashes(svg);
  ASSERT_EQ(drawn.size(), 3u);
  EXPECT_EQ(std::set<std::string>(drawn.begin(), drawn.end()).size(), 3u);
  // Circles, squares (rect) and triangles (polygon) on the lines and in the legend.
  EXPECT_EQ(occurrences(svg, "<circle"), 12 + 1);
  EXPECT_GE(occurrences(svg, "<polygon"), 12 + 1);
  // The legend's samples carry the dash patterns too (lines of width 2.5).
  for (const std::string& d : drawn) {
    if (!d.empty()) {
      EXPECT_NE(svg.find("stroke-width=\"2.5\" stroke-dasharray=\"" + d + "\""), std::string::npos) << d;
    }
  }
}

TEST(PlotStyles, ReferenceLinesAndOwnDashesStayAsGiven) {
  XYPlot plot = overlapping();
  plot.series[1].dash = "1 1";
  distinguish_series(plot, 1);  // series 0 is a reference line
  EXPECT_EQ(plot.series[0].dash, "");
  EXPECT_EQ(plot.series[0].style, PlotSeries::Style::line);
  EXPECT_EQ(plot.series[1].dash, "1 1");
  EXPECT_FALSE(plot.series[2].dash.empty());
  // Scatter series only get shapes.
  XYPlot scatter;
  scatter.add_scatter("a", {1, 2}, {1, 2}).add_scatter("b", {1, 2}, {1, 2});
  distinguish_series(scatter);
  EXPECT_EQ(scatter.series[1].style, PlotSeries::Style::markers);
  EXPECT_NE(scatter.series[0].marker, scatter.series[1].marker);
  EXPECT_EQ(scatter.series[1].dash, "");
  // Nothing to style: no change, no crash.
  distinguish_series(scatter, 5);
}

TEST(PlotStyles, EveryMarkerShapeRendersWellFormed) {
  XYPlot plot;
  for (const auto shape :
       {PlotSeries::Marker::circle, PlotSeries::Marker::square, PlotSeries::Marker::triangle,
        PlotSeries::Marker::diamond, PlotSeries::Marker::cross}) {
    plot.add_scatter("s", {1, 2, 3}, {3, 2, 1});
    plot.series.back().marker = shape;
  }
  const std::string svg = render_svg(plot);
  EXPECT_TRUE(sextant::testing::check_xml(svg).ok) << sextant::testing::check_xml(svg).error;
  EXPECT_EQ(occurrences(svg, "<circle"), 3 + 1);        // three points and the legend sample
  EXPECT_EQ(occurrences(svg, "<rect"), 1 + 1 + 3 + 1);  // background, frame, three squares, legend sample
}

// Issue 26: E7's chained estimate ran on its ground truth indistinguishably. The first trajectory
// is drawn wide and solid underneath, the others dashed, in the plot and in the legend.
TEST(PlotStyles, OverlappingTrajectoriesGetAWideReferenceAndDashes) {
  TrajectoryPlot plot;
  for (const char* name : {"truth", "estimate", "odometry"})
    plot.trajectories.push_back(
        {name, {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 0)}, "", {}, 10, 2.0});
  plot.trajectories[2].dash = "1 1";  // its own pattern is kept
  distinguish_trajectories(plot);
  EXPECT_EQ(plot.trajectories[0].width, 3.5);
  EXPECT_EQ(plot.trajectories[0].dash, "");
  EXPECT_EQ(plot.trajectories[1].dash, "8 4");
  EXPECT_EQ(plot.trajectories[2].dash, "1 1");
  const std::string svg = render_svg(plot);
  EXPECT_TRUE(sextant::testing::check_xml(svg).ok);
  EXPECT_EQ(occurrences(svg, "stroke-width=\"3.5\""), 1u);
  EXPECT_EQ(occurrences(svg, "stroke-dasharray=\"8 4\""), 2u);  // the line and its legend sample
}

}  // namespace
}  // namespace sextant
