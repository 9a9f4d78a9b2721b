#include "sextant/eval/plots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "sextant/core/atomic_file.hpp"
#include "svg_document.hpp"

namespace sextant {

namespace {

using svg::kBottom, svg::kLeft, svg::kRight, svg::kTop;

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();

  void add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return !(lo <= hi); }
};

/// Maps data values to pixels along one axis (linear or log10).
struct Axis {
  double lo = 0, hi = 1;
  bool log = false;
  double px_lo = 0, px_hi = 1;  // pixel of lo and of hi

  double value(double v) const { return log ? std::log10(v) : v; }
  double to_px(double v) const {
    const double a = value(lo), b = value(hi);
    return px_lo + (value(v) - a) / (b - a) * (px_hi - px_lo);
  }
  bool usable(double v) const { return std::isfinite(v) && (!log || v > 0.0); }
  std::vector<double> ticks() const {
    if (!log) return nice_ticks(lo, hi);
    std::vector<double> t;
    for (double e = std::ceil(std::log10(lo) - 1e-9); e <= std::log10(hi) + 1e-9; e += 1.0)
      t.push_back(std::pow(10.0, e));
    return t;
  }
};

/// A padded data range for an axis; `fixed_lo/hi` override when finite.
Axis make_axis(Range r, bool log, double fixed_lo, double fixed_hi) {
  Axis a;
  a.log = log;
  if (r.empty()) r = log ? Range{1.0, 10.0} : Range{0.0, 1.0};
  if (log) {
    a.lo = std::pow(10.0, std::floor(std::log10(r.lo)));
    a.hi = std::pow(10.0, std::ceil(std::log10(r.hi)));
    if (a.hi <= a.lo) a.hi = a.lo * 10.0;
  } else {
    double span = r.hi - r.lo;
    if (span <= 0.0) span = std::max(1.0, std::abs(r.lo));
    a.lo = r.lo - 0.04 * span;
    a.hi = r.hi + 0.04 * span;
    if (r.hi == r.lo) {
      a.lo = r.lo - 0.5 * span;
      a.hi = r.hi + 0.5 * span;
    }
  }
  if (std::isfinite(fixed_lo) && (!log || fixed_lo > 0)) a.lo = fixed_lo;
  if (std::isfinite(fixed_hi) && (!log || fixed_hi > 0)) a.hi = fixed_hi;
  if (!(a.hi > a.lo)) a.hi = a.lo + 1.0;
  return a;
}

void draw_title(svg::Document& doc, int width, const std::string& title) {
  if (!title.empty()) doc.text(width / 2.0, 24, title, 15, "middle");
}

/// Frame, grid, ticks and labels of a plot area.
void draw_axes(svg::Document& doc, const Axis& x, const Axis& y, const std::string& x_label,
               const std::string& y_label) {
  const double left = x.px_lo, right = x.px_hi, bottom = y.px_lo, top = y.px_hi;
  for (double t : x.ticks()) {
    if (t < x.lo - 1e-12 * std::abs(x.lo) || t > x.hi + 1e-12 * std::abs(x.hi)) continue;
    const double px = x.to_px(t);
    doc.line(px, top, px, bottom, "#e4e4e4");
    doc.line(px, bottom, px, bottom + 5, "#444");
    doc.text(px, bottom + 18, svg::tick_label(t), 11, "middle");
  }
  for (double t : y.ticks()) {
    if (t < y.lo - 1e-12 * std::abs(y.lo) || t > y.hi + 1e-12 * std::abs(y.hi)) continue;
    const double py = y.to_px(t);
    doc.line(left, py, right, py, "#e4e4e4");
    doc.line(left - 5, py, left, py, "#444");
    doc.text(left - 8, py + 4, svg::tick_label(t), 11, "end");
  }
  doc.rect(left, top, right - left, bottom - top, "none", "#444");
  if (!x_label.empty()) doc.text((left + right) / 2, bottom + 40, x_label, 13, "middle");
  if (!y_label.empty()) doc.text(18, (top + bottom) / 2, y_label, 13, "middle", -90);
}

/// Interpolates between two "#rrggbb" colours' components.
int channel(const char* hex) {
  return std::stoi(std::string(hex, 2), nullptr, 16);
}

std::string rgb(double r, double g, double b) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", static_cast<int>(std::lround(std::clamp(r, 0.0, 255.0))),
                static_cast<int>(std::lround(std::clamp(g, 0.0, 255.0))),
                static_cast<int>(std::lround(std::clamp(b, 0.0, 255.0))));
  return buf;
}

/// Black or white, whichever reads better on `background` ("#rrggbb").
std::string text_color_on(const std::string& background) {
  const double luminance =
      0.299 * channel(&background[1]) + 0.587 * channel(&background[3]) + 0.114 * channel(&background[5]);
  return luminance > 140 ? "#000" : "#fff";
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi) || target < 1) return ticks;
  if (hi < lo) std::swap(lo, hi);
  if (hi == lo) return {lo};
  const double raw = (hi - lo) / target;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * magnitude >= raw * 0.999) {
      step = m * magnitude;
      break;
    }
  // Integer multiples of the step (no accumulated rounding).
  const auto first = static_cast<long long>(std::ceil(lo / step - 1e-9));
  const auto last = static_cast<long long>(std::floor(hi / step + 1e-9));
  for (long long k = first; k <= last; ++k) ticks.push_back(static_cast<double>(k) * step);
  return ticks;
}

std::string colormap(double t) {
  // Viridis at nine anchors.
  static const double anchors[9][3] = {{68, 1, 84},    {71, 44, 122},  {59, 81, 139},
                                       {44, 113, 142}, {33, 144, 141}, {39, 173, 129},
                                       {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
  if (!std::isfinite(t)) t = 0.0;
  t = std::clamp(t, 0.0, 1.0) * 8.0;
  const int k = std::min(7, static_cast<int>(t));
  const double f = t - k;
  const double* a = anchors[k];
  const double* b = anchors[k + 1];
  return rgb(a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]));
}

XYPlot& XYPlot::add_scatter(const std::string& name, std::vector<double> xs, std::vector<double> ys) {
  series.push_back({name, std::move(xs), std::move(ys), PlotSeries::Style::markers, ""});
  return *this;
}

XYPlot& XYPlot::add_line(const std::string& name, std::vector<double> xs, std::vector<double> ys) {
  series.push_back({name, std::move(xs), std::move(ys), PlotSeries::Style::line, ""});
  return *this;
}

std::string render_svg(const XYPlot& plot) {
  Range xr, yr;
  Axis probe_x, probe_y;
  probe_x.log = plot.log_x;
  probe_y.log = plot.log_y;
  for (const PlotSeries& s : plot.series)
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
      if (probe_x.usable(s.x[i]) && probe_y.usable(s.y[i])) {
        xr.add(s.x[i]);
        yr.add(s.y[i]);
      }
  Axis x = make_axis(xr, plot.log_x, plot.x_min, plot.x_max);
  Axis y = make_axis(yr, plot.log_y, plot.y_min, plot.y_max);
  x.px_lo = kLeft;
  x.px_hi = plot.width - kRight;
  y.px_lo = plot.height - kBottom;
  y.px_hi = kTop;
  if (plot.equal_aspect && !plot.log_x && !plot.log_y) {
    const double per_px = std::max((x.hi - x.lo) / (x.px_hi - x.px_lo), (y.hi - y.lo) / (y.px_lo - y.px_hi));
    const double cx = 0.5 * (x.lo + x.hi), cy = 0.5 * (y.lo + y.hi);
    x.lo = cx - 0.5 * per_px * (x.px_hi - x.px_lo), x.hi = cx + 0.5 * per_px * (x.px_hi - x.px_lo);
    y.lo = cy - 0.5 * per_px * (y.px_lo - y.px_hi), y.hi = cy + 0.5 * per_px * (y.px_lo - y.px_hi);
  }

  svg::LegendEntries legend;
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const PlotSeries& s = plot.series[k];
    if (s.name.empty()) continue;
    // The sample: the line in the series' dash pattern, with its marker when it has markers.
    legend.emplace_back(s.name, s.color.empty() ? svg::palette(k) : s.color,
                        s.style == PlotSeries::Style::markers ? "" : s.dash,
                        s.style != PlotSeries::Style::line, s.marker, s.style != PlotSeries::Style::markers);
  }
  if (!plot.legend) legend.clear();
  const double legend_width = plot.width - kLeft - kRight;
  const int rows = svg::legend_rows(legend, legend_width);
  svg::Document doc(plot.width, plot.height + static_cast<int>(rows * svg::kLegendRow));
  draw_title(doc, plot.width, plot.title);
  draw_axes(doc, x, y, plot.x_label, plot.y_label);
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const PlotSeries& s = plot.series[k];
    const std::string color = s.color.empty() ? svg::palette(k) : s.color;
    std::vector<double> px, py;
    auto flush = [&] {
      if (s.style != PlotSeries::Style::markers && px.size() > 1)
        doc.polyline(px, py, color, 1.5, false, s.dash);
      px.clear();
      py.clear();
    };
    const std::size_t every = std::max<std::size_t>(1, s.marker_every);
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      // Points outside a fixed range are dropped, not clipped.
      const bool inside = x.usable(s.x[i]) && y.usable(s.y[i]) && s.x[i] >= x.lo && s.x[i] <= x.hi &&
                          s.y[i] >= y.lo && s.y[i] <= y.hi;
      if (!inside) {
        flush();
        continue;
      }
      px.push_back(x.to_px(s.x[i]));
      py.push_back(y.to_px(s.y[i]));
      if (s.style != PlotSeries::Style::line && i >= s.marker_offset && (i - s.marker_offset) % every == 0)
        doc.marker(px.back(), py.back(), s.marker_size, s.marker, color);
    }
    flush();
  }
  svg::draw_legend(doc, legend, kLeft, plot.height - 4, legend_width);
  return doc.finish();
}

std::string render_svg(const Heatmap& map) {
  const auto rows = static_cast<std::size_t>(map.values.rows()),
             cols = static_cast<std::size_t>(map.values.cols());
  double lo = map.value_min, hi = map.value_max;
  if (!(hi > lo)) {
    Range r;
    for (std::size_t i = 0; i < rows; ++i)
      for (std::size_t j = 0; j < cols; ++j)
        if (std::isfinite(map.values(i, j))) r.add(map.values(i, j));
    lo = r.empty() ? 0.0 : r.lo;
    hi = r.empty() || r.hi <= r.lo ? lo + 1.0 : r.hi;
  }
  const double bar_width = 18, bar_gap = 16, bar_labels = 56;
  const double left = kLeft, right = map.width - kRight - bar_width - bar_gap - bar_labels;
  const double top = kTop, bottom = map.height - kBottom;
  svg::Document doc(map.width, map.height);
  draw_title(doc, map.width, map.title);
  const double cw = cols ? (right - left) / cols : 0.0, ch = rows ? (bottom - top) / rows : 0.0;
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < cols; ++j) {
      const double v = map.values(i, j);
      const double x0 = left + j * cw, y0 = bottom - (i + 1) * ch;
      const std::string fill = std::isfinite(v) ? colormap((v - lo) / (hi - lo)) : "#cccccc";
      doc.rect(x0, y0, cw, ch, fill, "white", 0.5);
      if (map.annotate && std::isfinite(v)) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.*f", map.annotate_precision, v);
        doc.text(x0 + cw / 2, y0 + ch / 2 + 4, buf, 10, "middle", 0.0, text_color_on(fill));
      }
    }
  }
  doc.rect(left, top, right - left, bottom - top, "none", "#444");
  for (std::size_t j = 0; j < std::min(cols, map.x_ticks.size()); ++j)
    doc.text(left + (j + 0.5) * cw, bottom + 18, map.x_ticks[j], 11, "middle");
  for (std::size_t i = 0; i < std::min(rows, map.y_ticks.size()); ++i)
    doc.text(left - 8, bottom - (i + 0.5) * ch + 4, map.y_ticks[i], 11, "end");
  if (!map.x_label.empty()) doc.text((left + right) / 2, bottom + 40, map.x_label, 13, "middle");
  if (!map.y_label.empty()) doc.text(18, (top + bottom) / 2, map.y_label, 13, "middle", -90);
  // Colour bar: 64 stacked bands, ticks on its right.
  const double bx = right + bar_gap;
  const int bands = 64;
  for (int b = 0; b < bands; ++b) {
    const double h = (bottom - top) / bands;
    doc.rect(bx, bottom - (b + 1) * h, bar_width, h + 0.3, colormap((b + 0.5) / bands));
  }
  doc.rect(bx, top, bar_width, bottom - top, "none", "#444");
  for (double t : nice_ticks(lo, hi, 5)) {
    const double py = bottom - (t - lo) / (hi - lo) * (bottom - top);
    doc.line(bx + bar_width, py, bx + bar_width + 4, py, "#444");
    doc.text(bx + bar_width + 7, py + 4, svg::tick_label(t), 11);
  }
  if (!map.colorbar_label.empty())
    doc.text(map.width - 10, (top + bottom) / 2, map.colorbar_label, 12, "middle", -90);
  return doc.finish();
}

std::string render_svg(const TrajectoryPlot& plot) {
  const int second = plot.view == TrajectoryPlot::View::top_down ? 1 : 2;  // y or z against x
  Range xr, yr;
  for (const TrajectorySeries& t : plot.trajectories)
    for (const Eigen::Vector3d& p : t.positions)
      if (p.allFinite()) {
        xr.add(p.x());
        yr.add(p[second]);
      }
  if (xr.empty()) xr = yr = Range{0.0, 1.0};
  // Equal scale: widen the narrower range around its centre.
  const double left = kLeft, right = plot.width - kRight, top = kTop, bottom = plot.height - kBottom;
  double sx = std::max(xr.hi - xr.lo, 1e-9) * 1.08, sy = std::max(yr.hi - yr.lo, 1e-9) * 1.08;
  const double metres_per_px = std::max(sx / (right - left), sy / (bottom - top));
  sx = metres_per_px * (right - left);
  sy = metres_per_px * (bottom - top);
  Axis x, y;
  x.lo = (xr.lo + xr.hi - sx) / 2;
  x.hi = x.lo + sx;
  y.lo = (yr.lo + yr.hi - sy) / 2;
  y.hi = y.lo + sy;
  x.px_lo = left;
  x.px_hi = right;
  y.px_lo = bottom;
  y.px_hi = top;

  svg::LegendEntries legend;
  for (std::size_t k = 0; k < plot.trajectories.size(); ++k)
    if (!plot.trajectories[k].name.empty())
      legend.emplace_back(plot.trajectories[k].name,
                          plot.trajectories[k].color.empty() ? svg::palette(k) : plot.trajectories[k].color,
                          plot.trajectories[k].dash);
  const int rows = svg::legend_rows(legend, right - left);
  svg::Document doc(plot.width, plot.height + static_cast<int>(rows * svg::kLegendRow));
  draw_title(doc, plot.width, plot.title);
  draw_axes(doc, x, y, "x [m]", second == 1 ? "y [m]" : "z [m]");
  for (std::size_t k = 0; k < plot.trajectories.size(); ++k) {
    const TrajectorySeries& t = plot.trajectories[k];
    const std::string color = t.color.empty() ? svg::palette(k) : t.color;
    std::vector<double> px, py;
    auto flush = [&] {
      if (px.size() > 1) doc.polyline(px, py, color, t.width, false, t.dash);
      px.clear();
      py.clear();
    };
    for (const Eigen::Vector3d& p : t.positions) {
      if (!p.allFinite()) {
        flush();
        continue;
      }
      px.push_back(x.to_px(p.x()));
      py.push_back(y.to_px(p[second]));
    }
    flush();
    for (const Eigen::Vector3d& p : t.positions)
      if (p.allFinite()) {
        doc.circle(x.to_px(p.x()), y.to_px(p[second]), 3.5, color);  // start marker
        break;
      }
    // Covariance ellipses of the plotted components, as polygons in data space.
    const std::size_t every = std::max<std::size_t>(1, t.ellipse_every);
    for (std::size_t i = 0; i < std::min(t.covariances.size(), t.positions.size()); i += every) {
      const Eigen::Vector3d& c = t.positions[i];
      Eigen::Matrix2d cov;
      cov << t.covariances[i](0, 0), t.covariances[i](0, second), t.covariances[i](second, 0),
          t.covariances[i](second, second);
      if (!c.allFinite() || !cov.allFinite()) continue;
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
      const Eigen::Vector2d radii = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt() * t.ellipse_sigma;
      std::vector<double> ex, ey;
      for (int s = 0; s < 36; ++s) {
        const double a = 2.0 * M_PI * s / 36.0;
        const Eigen::Vector2d d =
            eig.eigenvectors() * Eigen::Vector2d(radii[0] * std::cos(a), radii[1] * std::sin(a));
        ex.push_back(x.to_px(c.x() + d.x()));
        ey.push_back(y.to_px(c[second] + d.y()));
      }
      doc.polyline(ex, ey, color, 0.8, true);
    }
  }
  svg::draw_legend(doc, legend, left, plot.height - 4, right - left);
  return doc.finish();
}

void write_svg(const std::string& svg, const std::filesystem::path& path) {
  write_file_atomically(path, svg);
}

}  // namespace sextant
