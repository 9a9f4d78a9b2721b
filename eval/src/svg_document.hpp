#pragma once
// Private helper of the eval module: builds an SVG document element by element, escaping text
// and formatting numbers with the classic locale so the output is well-formed XML.
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "sextant/eval/plots.hpp"

namespace sextant::svg {

/// Number → short text (up to 6 significant digits, no exponent for ordinary magnitudes).
std::string num(double v);
/// Tick label text: like num() but values within 1e-12 of zero print as "0".
std::string tick_label(double v);

class Document {
 public:
  Document(int width, int height);

  void rect(double x, double y, double w, double h, const std::string& fill,
            const std::string& stroke = "none", double stroke_width = 1.0);
  void line(double x1, double y1, double x2, double y2, const std::string& stroke, double width = 1.0,
            const std::string& dash = "");
  /// `dash`: SVG stroke-dasharray; empty = solid.
  void polyline(const std::vector<double>& xs, const std::vector<double>& ys, const std::string& stroke,
                double width = 1.5, bool closed = false, const std::string& dash = "");
  void circle(double cx, double cy, double r, const std::string& fill);
  /// A filled marker of radius r (a cross is stroked).
  void marker(double cx, double cy, double r, PlotSeries::Marker shape, const std::string& color);
  /// anchor: "start", "middle" or "end"; rotate in degrees about (x, y).
  void text(double x, double y, const std::string& content, double size = 12,
            const std::string& anchor = "start", double rotate = 0.0, const std::string& fill = "#222");
  /// Raw element markup (must be well-formed).
  void raw(const std::string& markup);
  std::string finish() const;

 private:
  std::ostringstream body_;
  int width_, height_;
};

/// A legend entry: name, colour, and the series' line style (dash pattern, marker) for its sample.
struct LegendEntry {
  LegendEntry(std::string name_, std::string color_, std::string dash_ = "", bool marked_ = false,
              PlotSeries::Marker marker_ = PlotSeries::Marker::circle, bool line_ = true)
      : name(std::move(name_)),
        color(std::move(color_)),
        dash(std::move(dash_)),
        marked(marked_),
        marker(marker_),
        line(line_) {}
  std::string name, color, dash;
  bool marked = false;  ///< draw `marker` on the sample
  PlotSeries::Marker marker = PlotSeries::Marker::circle;
  bool line = true;  ///< the sample has a line (a scatter series' shows its marker only)
};
using LegendEntries = std::vector<LegendEntry>;
constexpr double kLeft = 72, kRight = 24, kTop = 40, kBottom = 56;  ///< plot-area margins [px]
constexpr double kLegendRow = 18;                                   ///< height of one legend row [px]

/// Rows needed to flow the entries left to right within `width` px.
int legend_rows(const LegendEntries& entries, double width);
/// A legend outside the data, below the plot area: entries flow left to right from (left, top).
/// Each entry's sample is a short line in the entry's dash pattern with its marker, or a filled
/// square (`squares`, for bar charts).
void draw_legend(Document& doc, const LegendEntries& entries, double left, double top, double width,
                 bool squares = false);

/// The series palette.
const std::string& palette(std::size_t index);

}  // namespace sextant::svg
