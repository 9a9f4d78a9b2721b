// E8, fig. 5.17: "scan matching result at robot position given in figure 5.16" — the reference
// scan, the new scan placed by the dead-reckoning guess, and the new scan placed by ML-NDT
// (x, y, yaw), all in the reference scan's frame (eq. 3.46: ξ maps the new scan into it).
#include <cmath>

#include "kit/number_format.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/plots.hpp"
#include "sextant/filters/scan_matching_kf.hpp"
#include "simulation/room.hpp"

namespace sextant {
namespace {

Eigen::Isometry3d planar(const Eigen::Vector3d& xi) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(xi[2], Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(xi[0], xi[1], 0.0);
  return T;
}

void store(const PointCloud& cloud, const Eigen::Isometry3d& T, const std::string& name, RunRow& row) {
  std::vector<double> x, y;
  for (const Eigen::Vector3f& p : cloud.points()) {
    const Eigen::Vector3d q = T * p.cast<double>();
    x.push_back(q.x()), y.push_back(q.y());
  }
  row.series["match_" + name + "_x"] = x, row.series["match_" + name + "_y"] = y;
}

/// The points of series match_<name>_x/_y, in the plane z = 0.
PointCloud planar_cloud(const RunRow& row, const std::string& name) {
  const std::vector<double>&x = series_or_empty(row, "match_" + name + "_x"),
        &y = series_or_empty(row, "match_" + name + "_y");
  PointCloud cloud;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i)
    cloud.push_back(Eigen::Vector3f(static_cast<float>(x[i]), static_cast<float>(y[i]), 0.0f));
  return cloud;
}

}  // namespace

void record_scan_match(const RoomSim2dSettings& settings, const RoomSim2dRun& run, Matcher& matcher,
                       std::uint64_t seed, RunRow& row) {
  std::size_t pick = 0;
  double sharpest = -1;
  for (std::size_t k = 1; k < run.steps.size(); ++k) {
    const double turn = std::abs(wrap_angle(run.steps[k].truth.z() - run.steps[k - 1].truth.z()));
    if (run.steps[k].status == RoomSimStatus::kUpdated && turn > sharpest) sharpest = turn, pick = k;
  }
  if (pick == 0) return;
  const RoomSimStep &from = run.steps[pick - 1], &to = run.steps[pick];
  Rng rng(seed);
  const PointCloud reference = simulate_room_scan(settings, from.truth, rng);
  const PointCloud scan = simulate_room_scan(settings, to.truth, rng);
  const Eigen::Vector3d guess = AckermannScanMatchingEkf::relative_measurement(from.odometry, to.odometry);
  const Eigen::Vector3d truth = AckermannScanMatchingEkf::relative_measurement(from.truth, to.truth);
  matcher.set_reference(reference);
  const RegistrationResult match = matcher.align(scan, planar(guess));
  const Eigen::Vector3d xi(match.T.translation().x(), match.T.translation().y(),
                           std::atan2(match.T.linear()(1, 0), match.T.linear()(0, 0)));
  store(reference, Eigen::Isometry3d::Identity(), "reference", row);
  store(scan, planar(guess), "guess", row);
  store(scan, match.T, "matched", row);
  row.values["match_scan"] = static_cast<double>(pick);
  row.values["match_time_s"] = to.time;
  row.values["match_true_turn_deg"] = truth.z() * 180.0 / kPi;
  row.values["match_guess_error_m"] = (guess - truth).head<2>().norm();
  row.values["match_guess_error_deg"] = std::abs(wrap_angle(guess.z() - truth.z())) * 180.0 / kPi;
  row.values["match_error_m"] = (xi - truth).head<2>().norm();
  row.values["match_error_deg"] = std::abs(wrap_angle(xi.z() - truth.z())) * 180.0 / kPi;
  row.values["match_converged"] = match.converged ? 1.0 : 0.0;
}

ReportFigure scan_match_figure(const RunRow& row) {
  if (series_or_empty(row, "match_reference_x").empty()) return {};
  XYPlot plot{"Fig. 5.17: scan matching result at t = " + format_number(row.value("match_time_s"), 1) + " s",
              "x [m] (frame of the previous scan)",
              "y [m]",
              {}};
  plot.equal_aspect = true;
  plot.height = 520;
  // The reference scan as a line in beam order, broken where neighbouring returns jump (occlusions).
  std::vector<double> rx, ry;
  const std::vector<double>&x = series_or_empty(row, "match_reference_x"),
        &y = series_or_empty(row, "match_reference_y");
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    if (i > 0 && std::hypot(x[i] - x[i - 1], y[i] - y[i - 1]) > 0.5) rx.push_back(NAN), ry.push_back(NAN);
    rx.push_back(x[i]), ry.push_back(y[i]);
  }
  plot.add_line("previous scan (reference), drawn over the others", {}, {});  // legend entry only
  plot.series.back().color = "#222222";
  plot.add_scatter("new scan at the dead-reckoning guess (" +
                       format_number(row.value("match_guess_error_m"), 2) + " m, " +
                       format_number(row.value("match_guess_error_deg"), 1) + "° off)",
                   series_or_empty(row, "match_guess_x"), series_or_empty(row, "match_guess_y"));
  plot.series.back().color = "#d62728";
  plot.add_scatter("new scan after ML-NDT (" + format_number(row.value("match_error_m"), 3) + " m, " +
                       format_number(row.value("match_error_deg"), 2) + "° off)",
                   series_or_empty(row, "match_matched_x"), series_or_empty(row, "match_matched_y"));
  plot.series.back().color = "#1f77b4";
  plot.add_line("", rx, ry);
  plot.series.back().color = "#222222";
  return {"scan_match",
          "Fig. 5.17: one scan match of repetition " + std::to_string(row.repetition) + " (scan " +
              format_number(row.value("match_scan"), 0) +
              ", the sharpest turn: " + format_number(row.value("match_true_turn_deg"), 1) +
              "° since the previous scan). Both scans re-simulated at the run's true poses with fresh range "
              "noise; ML-NDT (x, y, yaw) from the dead-reckoning increment, as in the filter" +
              (row.value("match_converged") > 0 ? "" : "; the match did not converge"),
          render_svg(plot)};
}

ReportScene scan_match_scene(const RunRow& row) {
  if (series_or_empty(row, "match_reference_x").empty()) return {};
  ReportScene scene{"scan_match_3d",
                    "fig. 5.17 in 3D: the previous scan, and the new scan at the dead-reckoning guess and "
                    "after ML-NDT (repetition " +
                        std::to_string(row.repetition) + ", scan " +
                        format_number(row.value("match_scan"), 0) + ")",
                    {}};
  CloudView& view = scene.view;
  view.title = "Fig. 5.17: scan match at t = " + format_number(row.value("match_time_s"), 1) + " s";
  view.caption =
      "2D scans (z = 0) in the frame of the previous scan; the new scan's placement differs by "
      "state.";
  view.states = {"dead-reckoning guess (" + format_number(row.value("match_guess_error_m"), 2) + " m, " +
                     format_number(row.value("match_guess_error_deg"), 1) + "° off)",
                 "after ML-NDT (" + format_number(row.value("match_error_m"), 3) + " m, " +
                     format_number(row.value("match_error_deg"), 2) + "° off)"};
  view.clouds.push_back({"previous scan (reference)", planar_cloud(row, "reference"), "", {}, {}});
  view.clouds.push_back({"new scan at the guess", planar_cloud(row, "guess"), "", {}, {true, false}});
  view.clouds.push_back({"new scan after ML-NDT", planar_cloud(row, "matched"), "", {}, {false, true}});
  return scene;
}

}  // namespace sextant
