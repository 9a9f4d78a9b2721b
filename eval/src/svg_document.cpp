#include "svg_document.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <locale>

#include "sextant/eval/table.hpp"

namespace sextant::svg {

std::string num(double v) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out.precision(6);
  out << v;
  return out.str();
}

std::string tick_label(double v) {
  return num(std::abs(v) < 1e-12 ? 0.0 : v);
}

Document::Document(int width, int height) : width_(width), height_(height) {
  body_.imbue(std::locale::classic());
}

void Document::rect(double x, double y, double w, double h, const std::string& fill,
                    const std::string& stroke, double stroke_width) {
  body_ << "<rect x=\"" << num(x) << "\" y=\"" << num(y) << "\" width=\"" << num(w) << "\" height=\""
        << num(h) << "\" fill=\"" << escape_html(fill) << "\"";
  if (stroke != "none")
    body_ << " stroke=\"" << escape_html(stroke) << "\" stroke-width=\"" << num(stroke_width) << "\"";
  body_ << "/>\n";
}

void Document::line(double x1, double y1, double x2, double y2, const std::string& stroke, double width,
                    const std::string& dash) {
  body_ << "<line x1=\"" << num(x1) << "\" y1=\"" << num(y1) << "\" x2=\"" << num(x2) << "\" y2=\"" << num(y2)
        << "\" stroke=\"" << escape_html(stroke) << "\" stroke-width=\"" << num(width) << "\"";
  if (!dash.empty()) body_ << " stroke-dasharray=\"" << escape_html(dash) << "\"";
  body_ << "/>\n";
}

void Document::polyline(const std::vector<double>& xs, const std::vector<double>& ys,
                        const std::string& stroke, double width, bool closed, const std::string& dash) {
  if (xs.empty()) return;
  body_ << (closed ? "<polygon" : "<polyline") << " fill=\"none\" stroke=\"" << escape_html(stroke)
        << "\" stroke-width=\"" << num(width) << "\" stroke-linejoin=\"round\"";
  if (!dash.empty()) body_ << " stroke-dasharray=\"" << escape_html(dash) << "\"";
  body_ << " points=\"";
  for (std::size_t i = 0; i < xs.size() && i < ys.size(); ++i)
    body_ << (i ? " " : "") << num(xs[i]) << "," << num(ys[i]);
  body_ << "\"/>\n";
}

void Document::circle(double cx, double cy, double r, const std::string& fill) {
  body_ << "<circle cx=\"" << num(cx) << "\" cy=\"" << num(cy) << "\" r=\"" << num(r) << "\" fill=\""
        << escape_html(fill) << "\"/>\n";
}

void Document::marker(double cx, double cy, double r, PlotSeries::Marker shape, const std::string& color) {
  const auto polygon = [&](std::initializer_list<std::pair<double, double>> corners) {
    body_ << "<polygon fill=\"" << escape_html(color) << "\" points=\"";
    bool first = true;
    for (const auto& [dx, dy] : corners) {
      body_ << (first ? "" : " ") << num(cx + dx * r) << "," << num(cy + dy * r);
      first = false;
    }
    body_ << "\"/>\n";
  };
  switch (shape) {
    case PlotSeries::Marker::circle: circle(cx, cy, r, color); break;
    case PlotSeries::Marker::square: rect(cx - 0.85 * r, cy - 0.85 * r, 1.7 * r, 1.7 * r, color); break;
    case PlotSeries::Marker::triangle: polygon({{0.0, -1.2}, {1.1, 0.8}, {-1.1, 0.8}}); break;
    case PlotSeries::Marker::diamond: polygon({{0.0, -1.25}, {1.0, 0.0}, {0.0, 1.25}, {-1.0, 0.0}}); break;
    case PlotSeries::Marker::cross:
      line(cx - r, cy - r, cx + r, cy + r, color, 1.6);
      line(cx - r, cy + r, cx + r, cy - r, color, 1.6);
      break;
  }
}

void Document::text(double x, double y, const std::string& content, double size, const std::string& anchor,
                    double rotate, const std::string& fill) {
  body_ << "<text x=\"" << num(x) << "\" y=\"" << num(y) << "\" font-size=\"" << num(size)
        << "\" text-anchor=\"" << anchor << "\" fill=\"" << escape_html(fill) << "\"";
  if (rotate != 0.0)
    body_ << " transform=\"rotate(" << num(rotate) << " " << num(x) << " " << num(y) << ")\"";
  body_ << ">" << escape_html(content) << "</text>\n";
}

void Document::raw(const std::string& markup) {
  body_ << markup;
}

std::string Document::finish() const {
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width_ << "\" height=\"" << height_
      << "\" viewBox=\"0 0 " << width_ << " " << height_
      << "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n"
      << "<rect x=\"0\" y=\"0\" width=\"" << width_ << "\" height=\"" << height_ << "\" fill=\"white\"/>\n"
      << body_.str() << "</svg>\n";
  return out.str();
}

const std::string& palette(std::size_t index) {
  static const std::vector<std::string> colors{"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                               "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"};
  return colors[index % colors.size()];
}

namespace {

/// Width of one legend entry: swatch, gap, text (about 7 px per character, capped).
double legend_entry_width(const std::string& name) {
  return 34 + 7.0 * static_cast<double>(std::min<std::size_t>(name.size(), 60));
}

}  // namespace

int legend_rows(const LegendEntries& entries, double width) {
  if (entries.empty()) return 0;
  int rows = 1;
  double x = 0;
  for (const auto& e : entries) {
    const double w = legend_entry_width(e.name);
    if (x > 0 && x + w > width) {
      ++rows;
      x = 0;
    }
    x += w + 12;
  }
  return rows;
}

void draw_legend(Document& doc, const LegendEntries& entries, double left, double top, double width,
                 bool squares) {
  double x = 0, y = top + 12;
  for (const LegendEntry& e : entries) {
    const double w = legend_entry_width(e.name);
    if (x > 0 && x + w > width) {
      x = 0;
      y += kLegendRow;
    }
    if (squares) {
      doc.rect(left + x + 4, y - 10, 12, 12, e.color);
    } else {
      if (e.line) doc.line(left + x, y - 4, left + x + 18, y - 4, e.color, 2.5, e.dash);
      if (e.marked) doc.marker(left + x + 9, y - 4, 3.5, e.marker, e.color);
    }
    doc.text(left + x + 24, y, e.name, 11);
    x += w + 12;
  }
}

}  // namespace sextant::svg
