#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sextant/core/units.hpp"
#include "sextant/eval/plots.hpp"
#include "xml_check.hpp"

namespace sextant {
namespace {

using sextant::testing::check_xml;
using sextant::testing::occurrences;

TEST(Plots, NiceTicksAndColormap) {
  EXPECT_EQ(nice_ticks(0, 10, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  const std::vector<double> small = nice_ticks(-0.3, 0.3, 6);
  const std::vector<double> expected{-0.3, -0.2, -0.1, 0, 0.1, 0.2, 0.3};
  ASSERT_EQ(small.size(), expected.size());
  for (std::size_t k = 0; k < small.size(); ++k) EXPECT_NEAR(small[k], expected[k], 1e-12);
  EXPECT_EQ(nice_ticks(-0.3, 0.31, 6),
            (std::vector<double>{-0.2, 0, 0.2}));  // raw step 0.1017 rounds up to 0.2
  EXPECT_TRUE(nice_ticks(kNaN, 1).empty());
  EXPECT_EQ(colormap(0.0), "#440154");
  EXPECT_EQ(colormap(1.0), "#fde725");
  EXPECT_EQ(colormap(kNaN), "#440154");
}

TEST(Plots, LinePlotIsWellFormedWithSeriesLegendAndGaps) {
  XYPlot plot;
  plot.title = "Error <per> scan & iteration";
  plot.x_label = "scan";
  plot.y_label = "error [cm]";
  plot.add_line("NDT", {0, 1, 2, 3, 4}, {1, 2, kNaN, 4, 5});  // NaN splits the line in two
  plot.add_scatter("ML-NDT", {0, 1, 2}, {3, 2, 1});
  const std::string svg = render_svg(plot);
  const auto xml = check_xml(svg);
  ASSERT_TRUE(xml.ok) << xml.error;
  EXPECT_EQ(xml.elements.at("svg"), 1);
  EXPECT_EQ(xml.elements.at("polyline"), 2);    // the NDT line in two pieces (legend samples are <line>s)
  EXPECT_EQ(xml.elements.at("circle"), 3 + 1);  // the scatter's points and its legend sample's marker
  EXPECT_NE(svg.find("Error &lt;per&gt; scan &amp; iteration"), std::string::npos);
  EXPECT_NE(svg.find(">NDT</text>"), std::string::npos);
  EXPECT_NE(svg.find(">ML-NDT</text>"), std::string::npos);
  EXPECT_NE(svg.find(">error [cm]</text>"), std::string::npos);
}

TEST(Plots, LogAxisSkipsNonPositiveValues) {
  XYPlot plot;
  plot.log_y = true;
  plot.add_line("score", {1, 2, 3, 4}, {1000, 10, 0, 0.1});
  const std::string svg = render_svg(plot);
  ASSERT_TRUE(check_xml(svg).ok);
  EXPECT_NE(svg.find(">1000</text>"), std::string::npos);  // decade ticks
  EXPECT_NE(svg.find(">0.1</text>"), std::string::npos);
  EXPECT_EQ(occurrences(svg, "<polyline"), 1);  // (1,1000)–(2,10); (4,0.1) alone after the gap
}

TEST(Plots, EqualAspectWidensTheNarrowerRange) {
  XYPlot plot;
  plot.add_line("wall", {0, 100}, {0, 1});
  plot.equal_aspect = true;
  // x: 108 units over 544 px; y: the same scale over 324 px is about 64 units around 0.5, ticked
  // every 20 from −20 (no tick below zero without equal scales).
  const std::string svg = render_svg(plot);
  ASSERT_TRUE(check_xml(svg).ok);
  EXPECT_NE(svg.find(">-20</text>"), std::string::npos);
  plot.equal_aspect = false;
  EXPECT_EQ(render_svg(plot).find(">-20</text>"), std::string::npos);
}

TEST(Plots, EmptyPlotStillRenders) {
  const auto xml = check_xml(render_svg(XYPlot{}));
  EXPECT_TRUE(xml.ok) << xml.error;
}

TEST(Plots, HeatmapCellsColourBarAndMissing) {
  Heatmap map;
  map.title = "success rate";
  map.values.resize(3, 4);
  map.values << 0.0, 0.25, 0.5, 1.0,  //
      1.0, 1.0, kNaN, 0.5,            //
      0.1, 0.2, 0.3, 0.4;
  map.x_ticks = {"0", "10", "20", "30"};
  map.y_ticks = {"0°", "5°", "10°"};
  map.annotate = true;
  map.annotate_precision = 2;
  map.colorbar_label = "success";
  const std::string svg = render_svg(map);
  const auto xml = check_xml(svg);
  ASSERT_TRUE(xml.ok) << xml.error;
  // 12 cells + 64 colour bands + plot frame + bar frame + background.
  EXPECT_EQ(xml.elements.at("rect"), 12 + 64 + 3);
  EXPECT_EQ(occurrences(svg, "fill=\"#cccccc\""), 1);
  EXPECT_NE(svg.find(">0.25</text>"), std::string::npos);
  EXPECT_NE(svg.find(">10°</text>"), std::string::npos);
  EXPECT_NE(svg.find(colormap(1.0)), std::string::npos);
}

TEST(Plots, TrajectoriesTopDownAndSideWithEllipses) {
  TrajectoryPlot plot;
  plot.title = "hannover";
  TrajectorySeries truth{"ground truth", {}, "", {}, 10, 2.0};
  TrajectorySeries est{"EKF", {}, "", {}, 5, 2.0};
  for (int i = 0; i < 20; ++i) {
    const double a = 0.3 * i;
    truth.positions.emplace_back(10 * std::cos(a), 10 * std::sin(a), 0.1 * i);
    est.positions.emplace_back(10.5 * std::cos(a), 10.5 * std::sin(a), 0.12 * i);
    est.covariances.push_back(Eigen::Vector3d(0.2, 0.05, 0.01).asDiagonal());
  }
  plot.trajectories = {truth, est};
  const std::string top = render_svg(plot);
  const auto xml = check_xml(top);
  ASSERT_TRUE(xml.ok) << xml.error;
  EXPECT_EQ(xml.elements.at("polygon"), 4);  // ellipses at poses 0, 5, 10, 15
  EXPECT_EQ(xml.elements.at("polyline"), 2);
  EXPECT_NE(top.find(">y [m]</text>"), std::string::npos);
  plot.view = TrajectoryPlot::View::side;
  const std::string side = render_svg(plot);
  EXPECT_TRUE(check_xml(side).ok);
  EXPECT_NE(side.find(">z [m]</text>"), std::string::npos);
}

}  // namespace
}  // namespace sextant
