// Layout (E23, FastSLAM 2.0 against the Gaussian filters): the accuracy layout (errors, NEES, maps,
// claims) and the cost per scan against the map size, per filter and particle count — FastSLAM's
// update is O(M·log N) per particle (Montemerlo et al. 2003, §4: the tree-shared map), the EKF's
// O(N²) in the landmarks (thesis eq. 5.12–5.16). Methods with their own landmark source (rows
// *_x: extracted planes, per-particle association) also get an error figure of their own, since
// with every row in one figure the palette repeats.
#include <set>
#include <string>

#include "plane_slam/report.hpp"
#include "plane_slam/row_keys.hpp"

namespace sextant {

ReportSection accuracy_report(const ExperimentConfig&, const PlaneSlamParams&, const PlaneSlamRows&);

namespace fastslam_layout {

Table time_table(const PlaneSlamRows& data, std::uint64_t seed) {
  Table t;
  t.caption = "Time per scan against the map size (every repetition's scans, scan 0 left out)";
  t.label = "step_time_vs_map";
  t.note =
      "ms per scan = median of the filter step's time over every scan and repetition; slope = least "
      "squares of the step time against the number of landmarks mapped, with a 95 % bootstrap interval; "
      "growth = slope · (map range) / median time (below 0.5: flat). Times are this machine's, measured "
      "in the runs.";
  t.add_column("method")
      .add_number_column("ms per scan (median)", 3)
      .add_number_column("slope ms/landmark", 5)
      .add_number_column("slope lo", 5)
      .add_number_column("slope hi", 5)
      .add_number_column("growth", 2)
      .add_number_column("landmarks from", 0)
      .add_number_column("landmarks to", 0);
  for (const MethodRows* g : data.at(data.points.front())) {
    const TimeGrowth growth = time_growth(*g, keys::kStepMs, ++seed);
    t.add_row({Cell::text(g->name), number_or_missing(growth.median_ms),
               number_or_missing(growth.slope.estimate), number_or_missing(growth.slope.lo),
               number_or_missing(growth.slope.hi), number_or_missing(growth.growth.estimate),
               number_or_missing(growth.map_lo), number_or_missing(growth.map_hi)});
  }
  return t;
}

/// The groups of the methods whose landmark source is not the experiment's (E23's *_x rows).
PlaneSlamRows own_landmark_rows(const ExperimentConfig& config, const PlaneSlamParams& params,
                                const PlaneSlamRows& data) {
  std::set<std::string> names;
  for (const MethodConfig& m : config.methods)
    if (landmark_source(params, read_plane_slam_method(m.node, config.file)) != params.landmarks)
      names.insert(m.name);
  PlaneSlamRows out;
  out.points = data.points;
  out.repetitions = data.repetitions;
  for (const MethodRows& g : data.groups)
    if (names.count(g.name)) out.groups.push_back(g);
  return out;
}

}  // namespace fastslam_layout

ReportSection fastslam_report(const ExperimentConfig& config, const PlaneSlamParams& params,
                              const PlaneSlamRows& data) {
  ReportSection section = accuracy_report(config, params, data);
  if (data.points.empty() || data.at(data.points.front()).empty()) return section;
  section.tables.push_back(fastslam_layout::time_table(data, config.seed ^ 0x23u));
  section.figures.push_back(time_figure(data, keys::kStepMs, "step_time_vs_map", "Time per scan", true));
  const PlaneSlamRows own = fastslam_layout::own_landmark_rows(config, params, data);
  if (!own.groups.empty() && !own.at(own.points.front()).empty())
    section.figures.push_back(
        error_figure(own, own.points.front(), keys::kErrorM, keys::kOdometryErrorM,
                     "error_vs_scan_own_landmarks", "position error norm [m]",
                     std::string("Position error norm per scan, the methods with ") +
                         (params.landmarks == LandmarkSource::kTrue ? "extracted planes" : "true planes"),
                     {}));
  return section;
}

}  // namespace sextant
