#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "sextant/core/units.hpp"
#include "sextant/eval/bar_chart.hpp"
#include "xml_check.hpp"

namespace sextant {
namespace {

using sextant::testing::check_xml;

/// The value of attribute `name` in the SVG tag `tag`; empty when absent. (String scanning, not
/// std::regex: GCC 12's regex trips -Wmaybe-uninitialized in the sanitizer build.)
std::string attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const auto at = tag.find(key);
  if (at == std::string::npos) return "";
  const auto begin = at + key.size();
  return tag.substr(begin, tag.find('"', begin) - begin);
}

/// Every tag `<element …>` of the SVG, in order.
std::vector<std::string> tags(const std::string& svg, const std::string& element) {
  std::vector<std::string> out;
  for (auto at = svg.find("<" + element + " "); at != std::string::npos;
       at = svg.find("<" + element + " ", at + 1))
    out.push_back(svg.substr(at, svg.find('>', at) - at + 1));
  return out;
}

/// Heights of the bars filled with `color`: the <rect>s of that colour but the last, the legend's
/// 12 px square.
std::vector<double> bar_heights(const std::string& svg, const std::string& color) {
  std::vector<double> h;
  for (const std::string& rect : tags(svg, "rect"))
    if (attribute(rect, "fill") == color && !attribute(rect, "height").empty())
      h.push_back(std::stod(attribute(rect, "height")));
  EXPECT_FALSE(h.empty());
  if (!h.empty()) {
    EXPECT_EQ(h.back(), 12.0);  // the legend sample
    h.pop_back();
  }
  return h;
}

TEST(BarChart, OneBarPerSeriesAndCategoryWithHeightsToScale) {
  BarChart chart;
  chart.title = "Fig. 5.10 (a): mean <translation> error";
  chart.y_label = "mean error [cm]";
  chart.categories = {"tx", "ty", "tz"};
  chart.series.push_back({"odometry", {5, 2.5, kNaN}, "#111111"});  // NaN: no bar
  chart.series.push_back({"ML-NDT", {1, 10, 0}, "#222222"});
  chart.y_min = 0;
  chart.y_max = 10;
  const std::string svg = render_svg(chart);
  const auto xml = check_xml(svg);
  ASSERT_TRUE(xml.ok) << xml.error;
  // Plot area 420 − 56 − 40 = 324 px tall for 10 units: 32.4 px per unit.
  const std::vector<double> odometry = bar_heights(svg, "#111111");
  ASSERT_EQ(odometry.size(), 2u);
  EXPECT_NEAR(odometry[0], 162.0, 1e-6);
  EXPECT_NEAR(odometry[1], 81.0, 1e-6);
  const std::vector<double> mlndt = bar_heights(svg, "#222222");
  ASSERT_EQ(mlndt.size(), 3u);
  EXPECT_NEAR(mlndt[0], 32.4, 1e-6);
  EXPECT_NEAR(mlndt[1], 324.0, 1e-6);
  EXPECT_NEAR(mlndt[2], 0.0, 1e-9);
  for (const char* label : {">tx</text>", ">ty</text>", ">tz</text>", ">odometry</text>", ">ML-NDT</text>",
                            ">mean error [cm]</text>", "mean &lt;translation&gt; error"})
    EXPECT_NE(svg.find(label), std::string::npos) << label;
}

TEST(BarChart, LegendIsBelowThePlotAreaAndNegativeBarsGoDown) {
  BarChart chart;
  chart.categories = {"α", "β"};
  chart.series.push_back({"a", {-2, 1}, "#333333"});
  chart.series.push_back({"b", {1, 1}, ""});
  const std::string svg = render_svg(chart);
  ASSERT_TRUE(check_xml(svg).ok);
  // The legend row grows the figure below the 420 px of the chart.
  EXPECT_NE(svg.find("height=\"438\""), std::string::npos);
  const auto label = svg.find(">a</text>");
  ASSERT_NE(label, std::string::npos);
  const auto text = svg.rfind("<text ", label);
  ASSERT_NE(text, std::string::npos);
  EXPECT_GT(std::stod(attribute(svg.substr(text, label - text + 1), "y")), 420.0 - 56.0);
  // Range [−2, 1] padded by 5 % of 3 on both sides: the −2 bar is twice the +1 bar.
  const std::vector<double> a = bar_heights(svg, "#333333");
  ASSERT_EQ(a.size(), 2u);
  EXPECT_NEAR(a[0], 2.0 * a[1], 1e-3);                             // six significant digits in the SVG
  EXPECT_NE(svg.find("stroke-width=\"1.2\""), std::string::npos);  // the zero line
}

TEST(BarChart, EmptyChartStillRenders) {
  const auto xml = check_xml(render_svg(BarChart{}));
  EXPECT_TRUE(xml.ok) << xml.error;
}

}  // namespace
}  // namespace sextant
