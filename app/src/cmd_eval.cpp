// `sextant eval REFERENCE ESTIMATE [--format auto|tum|kitti] [--max-diff S] [--align se3|sim3|origin|none]
// [--delta N] [--delta-unit frames|m] [--ground-plane] [--json] [--plot DIR] [--view FILE] [--car-slip M]`:
// the accuracy of a trajectory one already has (evo_ape / evo_rpe's job, plus KITTI drift, Wulf and
// Kümmerle). TUM files pair by timestamp, KITTI files (no time) by index. For `sextant odometry`'s own files,
// with the defaults, it prints the very line odometry printed (both go through evaluate_trajectory).
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "number_options.hpp"
#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/trajectory_io.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/alignment_roll.hpp"
#include "sextant/eval/ground_plane.hpp"
#include "sextant/eval/plots.hpp"
#include "sextant/eval/run_view.hpp"
#include "sextant/eval/trajectory_evaluation.hpp"
#include "sextant/eval/vehicle_slip.hpp"
#include "sextant/pipeline/json.hpp"
#include "sextant/pipeline/trajectory_accuracy.hpp"

namespace sextant::cli {
namespace {

namespace fs = std::filesystem;

struct EvalOptions {
  std::string reference, estimate;
  std::string format = "auto";
  double max_diff = 0.01;
  std::string align = "se3";
  double delta = 1.0;
  std::string delta_unit = "frames";
  bool ground_plane = false;  ///< every metric on x, y and heading only (ground_plane.hpp)
  bool json = false;
  std::string plot;
  std::string view;       ///< the trajectories and per-pose errors as one HTML page (run_view.hpp)
  double car_slip = 0.0;  ///< > 0: list the reference's steps that slip sideways more than this [m]
};

struct LoadedTrajectory {
  Trajectory poses;
  TrajectoryFormat format = TrajectoryFormat::kTum;
};

LoadedTrajectory load(const std::string& file, const std::string& format) {
  LoadedTrajectory t;
  t.format = format == "tum"     ? TrajectoryFormat::kTum
             : format == "kitti" ? TrajectoryFormat::kKitti
                                 : detect_trajectory_format(file);
  TrajectoryReadNotes notes;
  t.poses =
      t.format == TrajectoryFormat::kTum ? read_tum_trajectory(file, &notes) : read_kitti_trajectory(file);
  if (const std::string note = trajectory_note(file, notes); !note.empty())
    std::cerr << "note: " << note << "\n";
  return t;
}

const char* format_name(TrajectoryFormat f) {
  return f == TrajectoryFormat::kTum ? "TUM" : "KITTI";
}

std::string fixed(double value, int digits) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value;
  return out.str();
}

std::string stats_row(const std::string& name, const SampleStats& s, double scale, int digits) {
  return "| " + name + " | " + fixed(s.rms * scale, digits) + " | " + fixed(s.mean * scale, digits) + " | " +
         fixed(s.median * scale, digits) + " | " + fixed(s.max * scale, digits) + " | " +
         std::to_string(s.count) + " |\n";
}

Json stats_json(const SampleStats& s, double scale) {
  return {{"rms", json_value(s.rms * scale)},
          {"mean", json_value(s.mean * scale)},
          {"median", json_value(s.median * scale)},
          {"max", json_value(s.max * scale)},
          {"count", s.count}};
}

/// "x 0.002 ± 0.004, y 0.085 ± 0.006, z …" (scaled).
std::string bias_text(const Eigen::Vector3d& mean, const Eigen::Vector3d& standard_error, double scale,
                      int digits, const std::string& unit) {
  std::string out;
  for (int a = 0; a < 3; ++a)
    out += std::string(a ? ", " : "") + "xyz"[a] + " " + fixed(mean(a) * scale, digits) + " ± " +
           fixed(standard_error(a) * scale, digits) + unit;
  return out;
}

Json vector_json(const Eigen::Vector3d& v, double scale) {
  return Json::array({json_value(v.x() * scale), json_value(v.y() * scale), json_value(v.z() * scale)});
}

/// Top view of both trajectories, and the ATE's translation error along the reference's path.
void write_plots(const fs::path& dir, const AssociatedPoses& pairs, const TrajectoryEvaluation& e) {
  TrajectoryPlot top;
  top.title = "Top view (estimate aligned: the ATE's alignment)";
  TrajectorySeries reference{"reference", {}, "#222222", {}, 10, 2.0};
  TrajectorySeries estimate{"estimate", {}, "#d62728", {}, 10, 2.0};
  for (const auto& T : pairs.reference) reference.positions.push_back(T.translation());
  for (const auto& T : e.aligned_estimate) estimate.positions.push_back(T.translation());
  top.trajectories = {reference, estimate};
  distinguish_trajectories(top);  // the estimate dashed over the wide reference
  write_svg(render_svg(top), dir / "trajectories.svg");

  XYPlot along;
  along.title = "ATE translation error along the path";
  along.x_label = "distance along the reference [m]";
  along.y_label = "error [m]";
  along.legend = false;
  along.add_line("", path_distances(pairs.reference), e.ate.translation_errors);
  write_svg(render_svg(along), dir / "error_along_path.svg");
}

/// With --car-slip: the reference's steps (pair k to k + 1) a car cannot make (vehicle_slip.hpp).
struct ReferenceSlip {
  VehicleSlip slip;
  std::vector<std::size_t> steps;
};

Json slip_json(const ReferenceSlip& r, double limit) {
  Json steps = Json::array();
  for (std::size_t k : r.steps) steps.push_back({{"step", k}, {"slip_m", json_value(r.slip.slip[k])}});
  return {{"limit_m", limit}, {"mounting_deg", json_value(r.slip.mounting * kDegPerRad)}, {"steps", steps}};
}

std::string slip_line(const ReferenceSlip& r, double limit) {
  std::string line = "reference: " + std::to_string(r.steps.size()) + " step" +
                     (r.steps.size() == 1 ? "" : "s") + " slip sideways more than " + fixed(limit, 2) +
                     " m, which a car cannot (the car's axis " +
                     fixed(std::round(r.slip.mounting * kDegPerRad * 10.0) / 10.0 + 0.0, 1) +  // no "-0.0"
                     "° from the sensor's x)";
  for (std::size_t i = 0; i < r.steps.size(); ++i)
    line += (i ? ", " : ": ") + std::to_string(r.steps[i]) + "→" + std::to_string(r.steps[i] + 1) + " " +
            fixed(r.slip.slip[r.steps[i]], 2) + " m";
  return line;
}

int run_eval(const EvalOptions& o) {
  if (!o.view.empty()) check_run_view_path(o.view);
  const LoadedTrajectory reference = load(o.reference, o.format);
  const LoadedTrajectory estimate = load(o.estimate, o.format);
  TrajectoryEvaluationSettings settings;
  if (!from_string(o.align, &settings.alignment))
    throw std::invalid_argument("--align must be se3, sim3, origin or none, not '" + o.align + "'");
  settings.rpe.unit = o.delta_unit == "m" ? RpeSettings::Unit::meters : RpeSettings::Unit::frames;
  settings.rpe.delta = o.delta;
  std::string why;
  if (!settings.rpe.valid(&why)) throw std::invalid_argument("--delta: " + why);

  // Pair by time when both files have it (TUM); KITTI files have none: by index.
  const bool by_stamp =
      reference.format == TrajectoryFormat::kTum && estimate.format == TrajectoryFormat::kTum;
  const AssociatedPoses pairs = by_stamp ? associate_by_stamp(estimate.poses, reference.poses, o.max_diff)
                                         : associate_by_index(estimate.poses, reference.poses);
  if (!pairs.status.ok) throw InputError(o.estimate, "", pairs.status.message);
  const TrajectoryEvaluation e = o.ground_plane
                                     ? evaluate_on_ground_plane(pairs.estimate, pairs.reference, settings)
                                     : evaluate_trajectory(pairs.estimate, pairs.reference, settings);
  if (!e.status.ok) throw InputError(o.estimate, "", e.status.message);
  const TrajectoryAccuracy a = trajectory_accuracy(e);
  const std::string per =
      o.delta == 1.0 && o.delta_unit == "frames"
          ? "scan"
          : fixed(o.delta, o.delta_unit == "m" ? 1 : 0) + (o.delta_unit == "m" ? " m" : " frames");
  if (!o.plot.empty()) write_plots(o.plot, pairs, e);
  if (!o.view.empty())
    write_run_view(evaluation_run_view(pairs, e,
                                       "sextant eval: " + fs::path(o.estimate).filename().string() +
                                           " against " + fs::path(o.reference).filename().string(),
                                       by_stamp),
                   o.view);
  std::optional<ReferenceSlip> slip;
  if (o.car_slip > 0.0) {
    slip.emplace();
    slip->slip = vehicle_slip(pairs.reference);
    slip->steps = slip->slip.slipping(o.car_slip);
  }

  const double deg = kDegPerRad;
  if (o.json) {
    Json j = {{"reference", o.reference},
              {"estimate", o.estimate},
              {"pairs", pairs.estimate.size()},
              {"associated_by", by_stamp ? "stamp" : "index"},
              {"ground_plane", o.ground_plane},
              {"unmatched_estimate", pairs.unmatched_estimate},
              {"unmatched_reference", pairs.unmatched_reference},
              {"largest_stamp_difference_s", json_value(pairs.largest_difference)},
              {"alignment",
               {{"kind", o.align},
                {"scale", json_value(e.ate.alignment.scale)},
                {"translation_m", json_value(e.ate.alignment.translation.norm())},
                {"roll_from_orientations", e.ate.roll_from_orientations}}},
              {"summary", accuracy_json(a)},
              {"ate_m", stats_json(e.ate.translation, 1.0)},
              {"ate_deg", stats_json(e.ate.rotation, deg)},
              {"rpe_m", stats_json(e.rpe.translation, 1.0)},
              {"rpe_deg", stats_json(e.rpe.rotation, deg)},
              {"rpe_bias",
               {{"rotation_deg", vector_json(e.rpe.mean_rotation_vector, deg)},
                {"rotation_deg_standard_error", vector_json(e.rpe.rotation_vector_standard_error, deg)},
                {"translation_m", vector_json(e.rpe.mean_translation, 1.0)},
                {"translation_m_standard_error", vector_json(e.rpe.translation_standard_error, 1.0)},
                {"scale_percent", json_value(100.0 * e.rpe.scale_error)},
                {"scale_percent_standard_error", json_value(100.0 * e.rpe.scale_standard_error)},
                {"scale_pairs", e.rpe.scale_pairs}}},
              {"rpe_delta", json_value(o.delta)},
              {"rpe_delta_unit", o.delta_unit},
              {"wulf_position_m", json_value(e.wulf.position_rms)},
              {"wulf_orientation_deg", json_value(e.wulf.orientation_rms * deg)},
              {"kummerle_translation_m", json_value(e.kummerle.translation_rms)},
              {"kummerle_rotation_deg", json_value(e.kummerle.rotation_rms * deg)}};
    if (slip) j["reference_slip"] = slip_json(*slip, o.car_slip);
    std::cout << json_line(j) << "\n";
    return 0;
  }
  if (verbosity() == Verbosity::kQuiet) {
    std::cout << accuracy_line(a, per) << "\n";
    return 0;
  }
  std::cout << "reference: " << o.reference << " (" << format_name(reference.format) << ", "
            << reference.poses.size() << " poses)\n"
            << "estimate:  " << o.estimate << " (" << format_name(estimate.format) << ", "
            << estimate.poses.size() << " poses)\n";
  if (by_stamp) {
    std::cout << "paired:    " << pairs.estimate.size() << " by timestamp (within " << o.max_diff
              << " s; largest difference " << pairs.largest_difference
              << " s); unmatched: " << pairs.unmatched_estimate << " of the estimate, "
              << pairs.unmatched_reference << " of the reference\n";
  } else {
    std::cout << "paired:    " << pairs.estimate.size() << " by index (KITTI files have no time)\n";
  }
  if (o.ground_plane)
    std::cout << "projected: both onto the ground plane after the alignment (x, y and heading; no height, "
                 "roll or pitch)\n";
  std::cout << "alignment: " << o.align;
  if (settings.alignment != Alignment::none) {
    std::cout << " (translation " << fixed(e.ate.alignment.translation.norm(), 3) << " m";
    if (settings.alignment == Alignment::sim3) std::cout << ", scale " << fixed(e.ate.alignment.scale, 4);
    std::cout << ")";
    if (e.ate.roll_from_orientations)
      std::cout << "; the positions lie near one line and leave the rotation about it free by more than "
                << kRollTolerance * kDegPerRad << "°, so it comes from the orientations";
  }
  std::cout << "\n" << accuracy_line(a, per) << "\n\n";
  std::cout << "| metric | RMS | mean | median | max | N |\n|---|---|---|---|---|---|\n"
            << stats_row("ATE translation [m]", e.ate.translation, 1.0, 3)
            << stats_row("ATE rotation [°]", e.ate.rotation, deg, 3)
            << stats_row("RPE translation [m], per " + per, e.rpe.translation, 1.0, 3)
            << stats_row("RPE rotation [°], per " + per, e.rpe.rotation, deg, 3) << "\n"
            << "Wulf (eqs. 6.1–6.3): position " << fixed(e.wulf.position_rms, 3) << " m, orientation "
            << fixed(e.wulf.orientation_rms * deg, 3)
            << "°; Kümmerle (eq. 6.6, consecutive poses): translation "
            << fixed(e.kummerle.translation_rms, 3) << " m, rotation "
            << fixed(e.kummerle.rotation_rms * deg, 3) << "°\n"
            << "RPE bias per " << per
            << " (signed mean ± standard error, in the first pose's frame): rotation "
            << bias_text(e.rpe.mean_rotation_vector, e.rpe.rotation_vector_standard_error, deg, 4, "°")
            << "; translation "
            << bias_text(e.rpe.mean_translation, e.rpe.translation_standard_error, 1.0, 4, " m") << "\n";
  if (e.rpe.scale_pairs > 0)
    std::cout << "motion scale error (along the reference's motion, over " << e.rpe.scale_pairs
              << " pairs): " << fixed(100.0 * e.rpe.scale_error, 4) << " ± "
              << fixed(100.0 * e.rpe.scale_standard_error, 4) << " %\n";
  if (verbosity() == Verbosity::kVerbose) {
    std::cout << "\n| KITTI segment [m] | segments | drift [%] | [°/100 m] |\n|---|---|---|---|\n";
    for (const KittiSegmentDrift& d : e.drift.per_length)
      std::cout << "| " << fixed(d.length, 0) << " | " << d.segments << " | "
                << (d.segments ? fixed(100.0 * d.translation, 2) : "–") << " | "
                << (d.segments ? fixed(100.0 * deg * d.rotation, 3) : "–") << " |\n";
  }
  if (slip) std::cout << slip_line(*slip, o.car_slip) << "\n";
  if (!o.plot.empty())
    std::cout << "wrote: " << (fs::path(o.plot) / "trajectories.svg").string() << ", error_along_path.svg\n";
  if (!o.view.empty())
    std::cout << "wrote: " << o.view << " (both trajectories and each pose's error, in 3D)\n";
  return 0;
}

}  // namespace

void add_eval_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<EvalOptions>();
  CLI::App* cmd = app.add_subcommand(
      "eval",
      "Accuracy of a trajectory against a reference (TUM or KITTI files): ATE, RPE, KITTI drift, Wulf "
      "and Kümmerle, after an alignment");
  cmd->add_option("reference", o->reference, "Reference (ground truth) trajectory: TUM or KITTI file")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("estimate", o->estimate, "Estimated trajectory: TUM or KITTI file")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--format", o->format, "File format: auto (8 numbers a line TUM, 12 KITTI), tum, kitti")
      ->check(CLI::IsMember({"auto", "tum", "kitti"}))
      ->capture_default_str();
  cmd->add_option("--max-diff", o->max_diff, "TUM: largest time difference of a pose pair [s]")
      ->check(finite_number(0.0))
      ->capture_default_str();
  cmd->add_option("--align", o->align,
                  "Alignment of the estimate before every metric: se3 (Umeyama), sim3 (with scale), origin "
                  "(first poses), none")
      ->check(CLI::IsMember({"se3", "sim3", "origin", "none"}))
      ->capture_default_str();
  cmd->add_option("--delta", o->delta, "RPE step between the poses of a pair")
      ->check(finite_number(0.0, true))
      ->capture_default_str();
  cmd->add_option("--delta-unit", o->delta_unit, "Unit of --delta: frames, or m along the reference's path")
      ->check(CLI::IsMember({"frames", "m"}))
      ->capture_default_str();
  cmd->add_flag(
      "--ground-plane", o->ground_plane,
      "Every metric on the ground plane: the estimate aligned in 3D (--align), then both trajectories' x, y "
      "and heading, without height, roll or pitch (for a reference whose height and tilt cannot be trusted)");
  cmd->add_flag("--json", o->json, "Print the results as one JSON object");
  cmd->add_option("--car-slip", o->car_slip,
                  "The reference is a car's: list its steps that slip sideways more than this [m] (a car "
                  "follows arcs; such a step cannot judge the estimate's; 0: off)")
      ->check(finite_number(0.0));
  cmd->add_option("--plot", o->plot,
                  "Write trajectories.svg (top view) and error_along_path.svg into this folder");
  cmd->add_option(
      "--view", o->view,
      "Write one self-contained HTML page (three.js, offline) of both trajectories, the estimate "
      "aligned as for the ATE and coloured by each pose's error; a click on a pose shows its time "
      "and error");
  cmd->callback([o, &exit_code] { exit_code = guarded([&] { return run_eval(*o); }); });
}

}  // namespace sextant::cli
