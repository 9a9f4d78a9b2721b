#include "registration/figures.hpp"

#include <cmath>

#include "registration/report.hpp"
#include "sextant/eval/bar_chart.hpp"
#include "sextant/eval/plots.hpp"

namespace sextant {
namespace {

const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

}  // namespace

ReportFigure parameter_error_figure(const std::string& id, const std::string& caption,
                                    const std::string& title, const std::vector<double>& scan,
                                    const std::vector<RegistrationError>& errors, bool translation,
                                    double limit) {
  XYPlot plot;
  plot.title = title;
  plot.x_label = "reference scan index";
  plot.y_label = translation ? "translation error [cm]" : "rotation error [deg]";
  const std::size_t first = translation ? 0 : 3;
  for (std::size_t k = first; k < first + 3; ++k) {
    std::vector<double> x, y;
    for (std::size_t i = 0; i < errors.size() && i < scan.size(); ++i) {
      x.push_back(scan[i]);
      y.push_back(errors[i].parameters[k]);
    }
    plot.add_line(parameter_names()[k], x, y);
    plot.series.back().style = PlotSeries::Style::line_and_markers;
    plot.series.back().color = kColours[k - first];
  }
  if (limit > 0 && !scan.empty()) {
    double lo = scan.front(), hi = scan.front();
    for (double s : scan) {
      lo = std::min(lo, s);
      hi = std::max(hi, s);
    }
    plot.add_line("±" + std::to_string(static_cast<int>(limit)) + " cm (success)", {lo, hi}, {limit, limit});
    plot.series.back().color = "#555555";
    plot.add_line("", {lo, hi}, {-limit, -limit});
    plot.series.back().color = "#555555";
  }
  return {id, caption, render_svg(plot)};
}

ReportFigure mean_error_figure(const std::string& id, const std::string& caption, const std::string& title,
                               const std::vector<std::string>& names,
                               const std::vector<std::array<double, 6>>& means, bool translation) {
  // Figs 5.10 and 5.14 are grouped bar charts: one group per parameter, one bar per method.
  BarChart chart;
  chart.title = title;
  chart.x_label = translation ? "translation parameter" : "rotation parameter";
  chart.y_label = translation ? "mean error [cm]" : "mean error [deg]";
  const std::size_t first = translation ? 0 : 3;
  for (std::size_t k = first; k < first + 3; ++k) chart.categories.push_back(parameter_names()[k]);
  for (std::size_t m = 0; m < names.size() && m < means.size(); ++m)
    chart.series.push_back({names[m],
                            {means[m][first], means[m][first + 1], means[m][first + 2]},
                            kColours[m % (sizeof kColours / sizeof kColours[0])]});
  return {id, caption, render_svg(chart)};
}

std::string fig_5_10_legend(const std::string& name, const RegistrationStats& stats, bool solved_only) {
  const std::size_t k = stats.successes, n = stats.count;
  const std::string rate = n == 0 ? "–" : format_number(100.0 * stats.success_rate, 0);
  const std::string counts = std::to_string(k) + "/" + std::to_string(n);
  // Fig. 5.10 averages each method over the pairs it solved, so a bar alone hides how many those are.
  return solved_only ? name + " (success " + rate + " %, " + counts + " pairs)"
                     : name + " (all " + std::to_string(n) + " pairs; " + rate + " % within the criterion)";
}

std::array<double, 6> mean_parameters(const std::vector<RegistrationError>& errors) {
  std::array<double, 6> sum{}, count{};
  for (const auto& e : errors) {
    for (std::size_t k = 0; k < 6; ++k) {
      if (!std::isfinite(e.parameters[k])) continue;
      sum[k] += e.parameters[k];
      count[k] += 1;
    }
  }
  for (std::size_t k = 0; k < 6; ++k) sum[k] = count[k] > 0 ? sum[k] / count[k] : NAN;
  return sum;
}

}  // namespace sextant
