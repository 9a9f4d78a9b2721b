// distinguish_series and distinguish_trajectories: dash patterns, widths and marker shapes per
// series, so overlapping curves of a plot stay distinguishable (plots.hpp).
#include <algorithm>
#include <array>

#include "sextant/eval/plots.hpp"

namespace sextant {

namespace {

const std::array<const char*, 6> kDashes{"", "8 4", "2 3", "10 3 2 3", "4 2", "12 3 2 3 2 3"};

}  // namespace

void distinguish_trajectories(TrajectoryPlot& plot) {
  for (std::size_t k = 0; k < plot.trajectories.size(); ++k) {
    TrajectorySeries& t = plot.trajectories[k];
    if (k == 0) t.width = 3.5;
    if (t.dash.empty()) t.dash = kDashes[k % kDashes.size()];
  }
}

void distinguish_series(XYPlot& plot, std::size_t first, std::size_t markers) {
  using Marker = PlotSeries::Marker;
  static const std::array<Marker, 5> kMarkers{Marker::circle, Marker::square, Marker::triangle,
                                              Marker::diamond, Marker::cross};
  if (first >= plot.series.size()) return;
  const std::size_t styled = plot.series.size() - first;
  for (std::size_t k = 0; k < styled; ++k) {
    PlotSeries& s = plot.series[first + k];
    s.marker = kMarkers[k % kMarkers.size()];
    if (s.style == PlotSeries::Style::markers) continue;
    if (s.dash.empty()) s.dash = kDashes[k % kDashes.size()];
    s.style = PlotSeries::Style::line_and_markers;
    s.marker_size = 3.5;
    const std::size_t n = std::min(s.x.size(), s.y.size());
    s.marker_every = std::max<std::size_t>(1, n / std::max<std::size_t>(1, markers));
    s.marker_offset = s.marker_every > 1 ? k * s.marker_every / styled : 0;
  }
}

}  // namespace sextant
