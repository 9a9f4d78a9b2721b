// E10's figures (§4.1): fig. 4.1, the merging problem, and fig. 4.2, the generated planes of both
// cases, drawn from the planes of repetition 0 (the fixed seed of table 4.1).
#include <cmath>

#include "kit/number_format.hpp"
#include "plane_features/merging.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/eval/plots.hpp"
#include "sextant/features/plane_fit.hpp"

namespace sextant {
namespace {

/// One plane of §4.1: points (x, shift + N(0, σ²), z) on the grid, fitted by PCA (as merging_test).
PlaneLandmark thesis_plane(const std::pair<Grid, Grid>& grid, double y_shift, double variance, Rng& rng,
                           std::vector<Eigen::Vector3f>* points) {
  std::vector<Eigen::Vector3f> pts;
  for (double x = grid.first.from; x <= grid.first.to + 1e-9; x += grid.first.step)
    for (double z = grid.second.from; z <= grid.second.to + 1e-9; z += grid.second.step)
      pts.emplace_back(float(x), float(y_shift + rng.normal(0.0, std::sqrt(variance))), float(z));
  std::vector<std::size_t> idx(pts.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  const PlaneFit fit = fit_plane(pts, idx, PlaneRefit::pca);
  if (points) points->insert(points->end(), pts.begin(), pts.end());
  return make_landmark(pts, idx, fit, Eigen::Vector3d(0, -100, 0));
}

}  // namespace

MergingCase make_case(const MergingParams& p, int which, std::uint64_t seed) {
  Rng rng(seed);
  MergingCase c;
  c.points.assign(3, {});
  for (std::size_t i = 0; i < 3; ++i) {
    const double shift = which == 2 && i > 0 ? p.case2_shift : 0.0;
    c.planes.push_back(thesis_plane(p.planes[i], shift, p.noise_variance, rng, &c.points[i]));
  }
  return c;
}

/// Fig. 4.2: the generated points of both cases seen along z (x against y), repetition 0.
ReportFigure planes_figure(const MergingParams& p, int which, std::uint64_t seed) {
  XYPlot plot{"Fig. 4.2 (" + std::string(which == 1 ? "a" : "b") + "): case " + std::to_string(which) +
                  ", generated planes (top view, x against y)",
              "x [m]",
              "y [m]",
              {}};
  const std::vector<std::vector<Eigen::Vector3f>> points = make_case(p, which, seed).points;
  for (std::size_t i = 0; i < 3; ++i) {
    std::vector<double> x, y;
    for (const auto& q : points[i]) x.push_back(q.x()), y.push_back(q.y());
    plot.series.push_back({"plane " + std::to_string(i + 1), x, y, PlotSeries::Style::markers, ""});
  }
  return {"generated_planes_case" + std::to_string(which),
          "Fig. 4.2 (" + std::string(which == 1 ? "a" : "b") + "): the three planes of case " +
              std::to_string(which) +
              (which == 2 ? " (planes 2 and 3 shifted along y)" : " (one infinite plane)") + ", seed " +
              std::to_string(seed) + "; planes 2 and 3 overlap for x = 15 … 25",
          render_svg(plot)};
}

/// Fig. 4.1 (the merging problem): case 1 face-on (x against z): the hulls and centres of the three
/// coplanar patches and the centre pairs the tests compare; the legend gives their C_o, C_t, C_p, d_c.
ReportFigure merging_problem_figure(const MergingParams& p, std::uint64_t seed) {
  XYPlot plot{"Fig. 4.1: merging problem (case 1, face-on view)", "x [m]", "z (in-plane axis) [m]", {}};
  plot.equal_aspect = true;
  plot.height = 300;
  const std::vector<PlaneLandmark> planes = make_case(p, 1, seed).planes;
  // Plane 3's outline and the c1–c3 link are drawn first (unnamed) so that plane 2's outline and the
  // c1–c2 link lie on top of them; their legend entries come after, with nothing left to draw.
  const auto hull = [&](std::size_t i, std::vector<double>& x, std::vector<double>& z) {
    for (std::size_t k = 0; k <= planes[i].hull.size() && !planes[i].hull.empty(); ++k)
      x.push_back(planes[i].hull[k % planes[i].hull.size()].x()),
          z.push_back(planes[i].hull[k % planes[i].hull.size()].z());
  };
  const char* const colours[5] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd"};
  plot.series.push_back({"", {}, {}, PlotSeries::Style::line, colours[2]});
  hull(2, plot.series.back().x, plot.series.back().y);
  plot.series.push_back({"",
                         {planes[0].centroid.x(), planes[2].centroid.x()},
                         {planes[0].centroid.z(), planes[2].centroid.z()},
                         PlotSeries::Style::line_and_markers,
                         colours[4]});
  for (std::size_t i = 0; i < 3; ++i) {
    plot.series.push_back({"plane " + std::to_string(i + 1) +
                               " hull (k = " + std::to_string(planes[i].inlier_count) + " points)",
                           {},
                           {},
                           PlotSeries::Style::line,
                           colours[i]});
    if (i < 2) hull(i, plot.series.back().x, plot.series.back().y);
  }
  for (std::size_t j : {std::size_t{1}, std::size_t{2}}) {
    const MergeCriteria m = merge_criteria(planes[0], planes[j], p.thresholds.min_variance);
    plot.series.push_back({"c1–c" + std::to_string(j + 1) + ": d_c = " + format_number(m.centre_distance, 1) +
                               ", C_o = " + format_number(m.orientation_deg, 1) + "°, C_t = " +
                               format_number(m.translation, 2) + ", C_p = " + format_number(m.closeness, 1) +
                               (m.passes(p.thresholds) ? " (merge)" : " (no merge)"),
                           {},
                           {},
                           PlotSeries::Style::line_and_markers,
                           colours[j + 2]});
    if (j == 1)
      plot.series.back().x = {planes[0].centroid.x(), planes[1].centroid.x()},
      plot.series.back().y = {planes[0].centroid.z(), planes[1].centroid.z()};
  }
  return {"merging_problem",
          "Fig. 4.1: the merging problem — three patches of one infinite plane (case 1, seed " +
              std::to_string(seed) +
              ") seen face-on; plane 2's outline lies on plane 3's for x = 15 … 25. "
              "The centres are far apart (d_c); the legend gives each pair's tests (merge when C_o < " +
              format_number(p.thresholds.orientation_deg, 0) + "°, C_t < " +
              format_number(p.thresholds.translation, 2) + " m and C_p < " +
              format_number(p.thresholds.closeness, 0) + ")",
          render_svg(plot)};
}

}  // namespace sextant
