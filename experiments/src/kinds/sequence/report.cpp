// What the sequence report layouts share, and the reference-block checks.
#include "sequence/report.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

#include "kit/row_keys.hpp"
#include "sequence/row_keys.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/plots.hpp"
#include "sextant/eval/statistics.hpp"

namespace sextant {
namespace {

std::vector<Eigen::Vector3d> positions(const PoseList& poses) {
  std::vector<Eigen::Vector3d> p;
  for (const auto& T : poses) p.push_back(T.translation());
  return p;
}

double mean_over(const std::vector<TrajectoryRun>& runs,
                 const std::function<double(const TrajectoryRun&)>& f) {
  std::vector<double> v;
  for (const auto& r : runs) v.push_back(f(r));
  return mean_of(v);
}

}  // namespace

void check_numbers(SettingsReader& in, const std::vector<const char*>& keys) {
  double x = 0;
  for (const char* key : keys) in.read(key, x);
}

void check_band(SettingsReader& in, const char* key) {
  std::vector<double> band;
  if (in.read(key, band) && (band.size() != 2 || !(band[0] < band[1])))
    in.fail(key, "key '" + std::string(key) + "': expected [low, high] with low < high");
}

std::vector<double> horizontal_errors(const PoseList& estimate, const PoseList& reference) {
  std::vector<double> e;
  for (std::size_t i = 0; i < std::min(estimate.size(), reference.size()); ++i)
    e.push_back((estimate[i].translation() - reference[i].translation()).head<2>().norm());
  return e;
}

std::vector<double> position_errors(const PoseList& estimate, const PoseList& reference) {
  std::vector<double> e;
  for (std::size_t i = 0; i < std::min(estimate.size(), reference.size()); ++i)
    e.push_back((estimate[i].translation() - reference[i].translation()).norm());
  return e;
}

std::vector<TrajectoryRun> trajectory_runs(const std::vector<RunSpec>& runs,
                                           const std::vector<const RunRow*>& rows) {
  std::vector<TrajectoryRun> out;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!rows[i] || !rows[i]->ok) continue;
    TrajectoryRun r;
    r.method = runs[i].method_index;
    r.repetition = runs[i].repetition;
    r.row = rows[i];
    r.truth = series_to_poses(series_or_empty(*rows[i], keys::kGroundTruth));
    r.odometry = series_to_poses(series_or_empty(*rows[i], keys::kOdometry));
    r.estimate = series_to_poses(series_or_empty(*rows[i], keys::kEstimate));
    r.matcher = series_to_poses(series_or_empty(*rows[i], keys::kMatcher));
    const auto& c = series_or_empty(*rows[i], keys::kCovarianceXyz);
    for (std::size_t k = 0; k + 9 <= c.size(); k += 9)
      r.covariance.push_back(Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(c.data() + k));
    if (r.truth.size() < 2 || r.odometry.size() != r.truth.size() || r.estimate.size() != r.truth.size())
      continue;
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<TrajectoryRun> runs_of_method(const std::vector<TrajectoryRun>& runs, std::size_t method) {
  std::vector<TrajectoryRun> out;
  for (const auto& r : runs)
    if (r.method == method) out.push_back(r);
  return out;
}

std::vector<double> run_values(const std::vector<TrajectoryRun>& runs, const std::string& key) {
  std::vector<double> v;
  for (const auto& r : runs) v.push_back(r.row->value(key));
  return v;
}

ReportFigure trajectory_figure(const std::string& id, const std::string& caption, const std::string& title,
                               const TrajectoryRun& run, const std::vector<NamedPoses>& estimates) {
  TrajectoryPlot plot;
  plot.title = title;
  plot.width = 760;
  plot.height = 620;
  const auto series = [](const std::string& name, const PoseList& poses, const std::string& color) {
    TrajectorySeries s;
    s.name = name;
    s.positions = positions(poses);
    s.color = color;
    return s;
  };
  plot.trajectories.push_back(series("ground truth", run.truth, "#2a9d3f"));
  plot.trajectories.push_back(series("odometry (2D)", run.odometry, "#e07b00"));
  for (const auto& e : estimates) {
    TrajectorySeries s = series(e.name, *e.poses, e.color);
    s.covariances = e.covariances;
    s.ellipse_every = 1;
    s.ellipse_sigma = e.ellipse_sigma;
    plot.trajectories.push_back(std::move(s));
  }
  distinguish_trajectories(plot);  // the estimate runs on the ground truth: dashed over a wide line
  return {id, caption, render_svg(plot)};
}

ReportFigure error_figure(const std::string& id, const std::string& caption, const std::string& title,
                          const TrajectoryRun& run, const std::vector<NamedPoses>& estimates) {
  XYPlot plot;
  plot.title = title;
  plot.x_label = "scan";
  plot.y_label = "horizontal position error [m]";
  std::vector<double> x;
  for (std::size_t k = 0; k < run.truth.size(); ++k) x.push_back(static_cast<double>(k + 1));
  plot.series.push_back(
      {"odometry (2D)", x, horizontal_errors(run.odometry, run.truth), PlotSeries::Style::line, "#e07b00"});
  for (const auto& e : estimates)
    plot.series.push_back(
        {e.name, x, horizontal_errors(*e.poses, run.truth), PlotSeries::Style::line, e.color});
  plot.y_min = 0;
  return {id, caption, render_svg(plot)};
}

void add_tum_files(ReportSection& section, const TrajectoryRun& run, std::size_t first_scan,
                   const std::vector<NamedPoses>& trajectories) {
  for (const auto& t : trajectories) {
    ReportTrajectory file;
    file.id = "trajectory_";
    for (const char ch : t.name)
      file.id += std::isalnum(static_cast<unsigned char>(ch)) ? static_cast<char>(std::tolower(ch)) : '_';
    file.caption = t.name + " (repetition " + std::to_string(run.repetition) + ")";
    for (std::size_t k = 0; k < t.poses->size(); ++k)
      file.poses.push_back({static_cast<double>(first_scan + k), (*t.poses)[k]});
    section.trajectories.push_back(std::move(file));
  }
}

Table metrics_table(const std::string& caption, const std::string& label, std::size_t runs) {
  Table t;
  t.caption = caption;
  t.label = label;
  t.note = "Means over " + std::to_string(runs) +
           " run(s). Position errors against the ground truth; xy = horizontal (the odometry is 2D, z = 0). "
           "RPE: evo's relative pose error over one scan. KITTI drift: the devkit's mean translation error "
           "per segment length (100–800 m segments; missing when the path is shorter).";
  t.add_column("trajectory")
      .add_number_column("end xy m", 2)
      .add_number_column("end 3D m", 2)
      .add_number_column("mean xy m", 2)
      .add_number_column("RPE mean cm", 1)
      .add_number_column("RPE max cm", 1)
      .add_number_column("RPE rot deg", 3)
      .add_number_column("KITTI drift %", 2);
  return t;
}

void add_metric_rows(Table& table, const std::string& label, const std::vector<TrajectoryRun>& runs,
                     PoseList TrajectoryRun::*member) {
  const auto ok = [&](const TrajectoryRun& r) { return (r.*member).size() == r.truth.size(); };
  const double end_xy = mean_over(runs, [&](const TrajectoryRun& r) {
    return ok(r) ? horizontal_errors(r.*member, r.truth).back() : kNaN;
  });
  const double end_3d = mean_over(runs, [&](const TrajectoryRun& r) {
    return ok(r) ? position_errors(r.*member, r.truth).back() : kNaN;
  });
  const double mean_xy = mean_over(runs, [&](const TrajectoryRun& r) {
    return ok(r) ? mean_of(horizontal_errors(r.*member, r.truth)) : kNaN;
  });
  const double rpe_t = mean_over(runs, [&](const TrajectoryRun& r) {
    return ok(r) ? relative_pose_error(r.*member, r.truth).translation.mean * 100.0 : kNaN;
  });
  const double rpe_t_max = mean_over(runs, [&](const TrajectoryRun& r) {
    return ok(r) ? relative_pose_error(r.*member, r.truth).translation.max * 100.0 : kNaN;
  });
  const double rpe_r = mean_over(runs, [&](const TrajectoryRun& r) {
    return ok(r) ? relative_pose_error(r.*member, r.truth).rotation.mean * 180.0 / kPi : kNaN;
  });
  const double drift = mean_over(runs, [&](const TrajectoryRun& r) {
    if (!ok(r)) return kNaN;
    const KittiDriftResult d = kitti_drift(r.*member, r.truth);
    return d.status.ok && d.segments > 0 ? d.translation * 100.0 : kNaN;
  });
  table.add_row({Cell::text(label), number_or_missing(end_xy), number_or_missing(end_3d),
                 number_or_missing(mean_xy), number_or_missing(rpe_t, 1), number_or_missing(rpe_t_max, 1),
                 number_or_missing(rpe_r, 3), number_or_missing(drift)});
}

}  // namespace sextant
