#include <algorithm>
#include <cmath>

#include "sextant/eval/bar_chart.hpp"
#include "sextant/eval/plots.hpp"
#include "svg_document.hpp"

namespace sextant {
namespace {

using svg::kBottom, svg::kLeft, svg::kRight, svg::kTop;

constexpr double kGroupFill = 0.8;  ///< share of a group's width covered by its bars

/// The value range: the data and zero, padded by 5 % on the sides that hold data.
void value_range(const BarChart& chart, double* lo, double* hi) {
  double a = 0.0, b = 0.0;
  for (const BarSeries& s : chart.series)
    for (double v : s.values)
      if (std::isfinite(v)) a = std::min(a, v), b = std::max(b, v);
  const double span = b - a > 0 ? b - a : 1.0;
  if (a < 0) a -= 0.05 * span;
  if (b > 0 || a == 0) b += 0.05 * span;
  if (std::isfinite(chart.y_min)) a = chart.y_min;
  if (std::isfinite(chart.y_max)) b = chart.y_max;
  if (!(b > a)) b = a + 1.0;
  *lo = a;
  *hi = b;
}

}  // namespace

std::string render_svg(const BarChart& chart) {
  double lo = 0, hi = 1;
  value_range(chart, &lo, &hi);
  const double left = kLeft, right = chart.width - kRight, top = kTop, bottom = chart.height - kBottom;
  const auto to_px = [&](double v) {
    return bottom - (std::clamp(v, lo, hi) - lo) / (hi - lo) * (bottom - top);
  };

  svg::LegendEntries legend;
  for (std::size_t k = 0; k < chart.series.size(); ++k)
    if (!chart.series[k].name.empty())
      legend.emplace_back(chart.series[k].name,
                          chart.series[k].color.empty() ? svg::palette(k) : chart.series[k].color);
  const int rows = svg::legend_rows(legend, right - left);
  svg::Document doc(chart.width, chart.height + static_cast<int>(rows * svg::kLegendRow));
  if (!chart.title.empty()) doc.text(chart.width / 2.0, 24, chart.title, 15, "middle");

  // Grid and value ticks.
  for (double t : nice_ticks(lo, hi)) {
    if (t < lo - 1e-12 * std::abs(lo) || t > hi + 1e-12 * std::abs(hi)) continue;
    const double py = to_px(t);
    doc.line(left, py, right, py, "#e4e4e4");
    doc.line(left - 5, py, left, py, "#444");
    doc.text(left - 8, py + 4, svg::tick_label(t), 11, "end");
  }
  // Bars: group g spans [left + g·w, left + (g + 1)·w]; its bars fill kGroupFill of it.
  const std::size_t groups = chart.categories.size();
  const double group_width = groups ? (right - left) / static_cast<double>(groups) : 0.0;
  const double bar_width =
      chart.series.empty() ? 0.0 : group_width * kGroupFill / static_cast<double>(chart.series.size());
  const double zero = to_px(0.0);
  for (std::size_t g = 0; g < groups; ++g) {
    const double x0 = left + g * group_width + 0.5 * (1.0 - kGroupFill) * group_width;
    for (std::size_t k = 0; k < chart.series.size(); ++k) {
      const BarSeries& s = chart.series[k];
      if (g >= s.values.size() || !std::isfinite(s.values[g])) continue;
      const double end = to_px(s.values[g]);
      doc.rect(x0 + k * bar_width, std::min(zero, end), std::max(bar_width - 1.0, 1.0), std::abs(end - zero),
               s.color.empty() ? svg::palette(k) : s.color);
    }
    doc.text(left + (g + 0.5) * group_width, bottom + 18, chart.categories[g], 12, "middle");
    if (g > 0) doc.line(left + g * group_width, bottom, left + g * group_width, bottom + 5, "#444");
  }
  if (lo < 0 && hi > 0) doc.line(left, zero, right, zero, "#444", 1.2);
  doc.rect(left, top, right - left, bottom - top, "none", "#444");
  if (!chart.x_label.empty()) doc.text((left + right) / 2, bottom + 40, chart.x_label, 13, "middle");
  if (!chart.y_label.empty()) doc.text(18, (top + bottom) / 2, chart.y_label, 13, "middle", -90);
  svg::draw_legend(doc, legend, left, chart.height - 4, right - left, /*squares=*/true);
  return doc.finish();
}

}  // namespace sextant
