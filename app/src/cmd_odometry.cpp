// `sextant odometry <dataset> [--method mlndt] [--preset …] [--guess odometry|constant_velocity|identity]
// [--map scan|local_map] [--first N] [--scans N] [--view run.html] --out DIR`: chains registrations over a
// sequence (§5.1.3's dead reckoning by a matcher) of a uos folder, a KITTI odometry sequence folder, a
// folder of scans, a recording (--topic, --start, --duration, --every choose its scans) or the built-in
// campus (`campus`), writes the trajectory as TUM and KITTI files, steps.csv, metrics.json and
// provenance.json (with --map-out the run's map, with --view its HTML page), and prints ATE / RPE /
// KITTI drift against the dataset's ground truth.
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include <oneapi/tbb/global_control.h>

#include "commands.hpp"
#include "map_output.hpp"
#include "matcher_options.hpp"
#include "number_options.hpp"
#include "odometry_report.hpp"
#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/output_folder.hpp"
#include "sextant/core/progress.hpp"
#include "sextant/eval/run_view.hpp"
#include "sextant/matchers/matcher_choice.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/pipeline/dataset_argument.hpp"
#include "sextant/pipeline/json.hpp"
#include "sextant/pipeline/odometry_loop_closure.hpp"
#include "sextant/pipeline/odometry_output.hpp"
#include "sextant/pipeline/odometry_request.hpp"
#include "sextant/pipeline/odometry_view.hpp"
#include "sextant/pipeline/provenance.hpp"
#include "sextant/pipeline/run_map_builder.hpp"

namespace sextant::cli {
namespace {

namespace fs = std::filesystem;

std::string yes_no(bool b) {
  return b ? "yes" : "no";
}

/// Where --view is written: into the run's folder when it names a file there (it is then one of the
/// run's files, swapped in with them), else where it says. Checked before the run: the folder exists
/// and three.js is installed.
fs::path view_target(const OdometryOptions& o, const OutputFolder& folder) {
  const fs::path view = fs::absolute(o.view);
  if (!view.filename().empty() && !fs::is_directory(view) &&
      fs::weakly_canonical(view.parent_path()) == fs::weakly_canonical(fs::absolute(folder.target()))) {
    check_run_view_scripts();
    return folder.staging() / view.filename();
  }
  check_run_view_path(o.view);
  return view;
}

int run_odometry_command(const OdometryOptions& o) {
  const std::string start = iso_time_now();
  // Arguments first (cheap), then the dataset.
  // Unknown names and bad settings stop here; `config.resolved` is every setting they run with.
  const MatcherConfig config = read_matcher_config(o);
  if (o.print_config) {
    std::cout << YAML::Dump(config.resolved) << "\n";
    return 0;
  }
  OdometryRequest request;
  request.method = o.method;
  request.registration = {matcher_choice(config.spec.matcher), sampler_factory(config.spec.sampler)};
  request.guess = o.guess;
  request.map = o.map;
  request.sensor = o.sensor;
  request.platform = o.platform;
  if (o.whole_scans) request.common_view = false;
  if (o.common_view) request.common_view = true;
  request.first = o.first;
  request.scans = o.scans;
  request.local_map_scans = o.local_map_scans;
  request.min_range = o.min_range;
  request.max_acceleration = o.max_acceleration;
  request.seed = o.seed;
  request.recover = !o.no_recover;
  request.deskew = !o.no_deskew;
  OdometrySettings settings = odometry_settings(request, Face::cli);
  std::optional<LoopCandidateSource> loop_source;
  if (!o.loop_closure.empty()) {
    LoopCandidateSource source{};
    if (!from_string(o.loop_closure, &source))
      throw InputError("--loop-closure", "",
                       "'" + o.loop_closure + "': expected proximity, descriptor or both");
    loop_source = source;
  }
  std::optional<MapOutput> map_output;  // its extension is checked now, before the run
  if (!o.map_out.empty()) map_output.emplace(o.map_out, o.out);
  RunMapSettings map_settings;
  if (o.map_voxel > 0.0) map_settings.voxel = o.map_voxel;
  map_settings.trusted_only = o.map_trusted_only;
  std::optional<tbb::global_control> threads;
  if (o.jobs > 0)
    threads.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(o.jobs));

  const std::unique_ptr<Dataset> dataset =
      open_dataset_argument(o.dataset, o.poses.empty() ? std::nullopt : std::optional<std::string>(o.poses),
                            o.campus_seed, Face::cli, o.recording_selection());
  const DatasetMetadata& meta = dataset->metadata();
  const OdometryPlan plan = plan_odometry(std::move(settings), request, *dataset, o.dataset, Face::cli);
  const OdometrySettings& s = plan.settings;
  const std::size_t scans = plan.scans;
  // Taken before the run: a second run into the same folder is refused now, not after it.
  OutputFolder folder(o.out, "sextant odometry");
  const fs::path view = o.view.empty() ? fs::path() : view_target(o, folder);

  const bool quiet = verbosity() == Verbosity::kQuiet;
  if (!quiet)
    std::cout << "dataset:  " << (meta.path.empty() ? meta.name : meta.path.string()) << " (" << meta.format
              << ", " << dataset->size() << " scans; odometry " << yes_no(meta.has_odometry)
              << ", ground truth " << yes_no(meta.has_ground_truth) << "), scans " << o.first << "–"
              << o.first + scans - 1 << "\n"
              << "method:   " << describe_matcher(config) << ", sampling " << o.sampling << ", guess "
              << to_string(s.guess) << (o.guess.empty() ? " (default for this dataset)" : "") << ", map "
              << to_string(s.map)
              << (s.map == OdometryMap::local_map ? " of " + std::to_string(s.local_map_scans) + " scans"
                                                  : "")
              << "\n"
              << "deskew:   " << deskew_line(s, *dataset, o.first, Face::cli) << "\n";
  if (!quiet) {
    for (const std::string& note : meta.notes) std::cout << "note:     " << note << "\n";
    const std::string trust_note = uncalibrated_trust_note(settings_off_the_defaults(config));
    if (!trust_note.empty()) std::cout << "note:     " << trust_note << "\n";
  }
  std::cout << std::flush;

  const auto t0 = std::chrono::steady_clock::now();
  std::optional<Progress> progress;  // drawn only on a terminal
  if (o.no_progress || quiet) {
    progress.emplace(scans - 1, "odometry", nullptr);
  } else {
    progress.emplace(scans - 1, "odometry");
  }
  // The map is built as the run goes; with --loop-closure, after the loops are closed, from the
  // closed poses (run_map_builder.hpp).
  // The view draws the same map.
  const bool wants_map = map_output || !o.view.empty();
  std::optional<RunMapBuilder> map;
  if (wants_map && !loop_source) map.emplace(map_settings);
  const OdometryResult result = run_odometry(
      *dataset, s, o.first, scans, [&](std::size_t, std::size_t) { progress->tick(); },
      map ? map->observer() : OdometryScanObserver{});
  progress->finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!quiet) std::cout << "sensor:   " << sensor_line(s, result) << "\n";
  std::optional<OdometryLoopClosure> loops;
  if (loop_source) loops = close_odometry_loops(*dataset, o.first, scans, result, s, *loop_source);
  const std::vector<Eigen::Isometry3d>& poses = loops ? loops->closing.poses : result.poses;
  if (wants_map && loops)
    map.emplace(
        build_run_map(*dataset, o.first, poses, result.steps, s.min_range, map_settings, result.sweeps));
  const std::optional<RunMapSummary> map_summary =
      map_output ? std::optional<RunMapSummary>(map->summary()) : std::nullopt;

  OdometryCounts counts = odometry_counts(result);
  const auto truth = ground_truth_of(*dataset, o.first, scans);
  std::optional<TrajectoryAccuracy> estimate_accuracy, odometry_accuracy;
  std::string estimate_problem, odometry_problem;  // why an accuracy could not be computed
  if (truth && scans >= 2) {
    estimate_accuracy = trajectory_accuracy(poses, *truth, &estimate_problem);
    counts.trusted_off_reference = trusted_steps_off_reference(result, *truth, result.tolerance);
    if (const auto odometry = odometry_of(*dataset, o.first, scans))
      odometry_accuracy = trajectory_accuracy(*odometry, *truth, &odometry_problem);
  }

  const fs::path out = folder.staging();
  write_trajectories(out, *dataset, o.first, poses, truth);
  write_steps_csv(out / "steps.csv", o.first, result, truth);
  std::optional<LoopClosureSummary> loop_summary;
  if (loops) {
    write_trajectories(out / "chained", *dataset, o.first, result.poses, std::nullopt);
    write_loop_closures_csv(out / "loop_closures.csv", o.first, *loops, truth);
    loop_summary = LoopClosureSummary{o.loop_closure,
                                      loops->closing.attempts.size(),
                                      loops->closing.accepted(),
                                      loops->seconds,
                                      loops->descriptor_seconds,
                                      std::nullopt,
                                      {}};
    std::string problem;
    if (truth && scans >= 2) loop_summary->chained = trajectory_accuracy(result.poses, *truth, &problem);
    if (truth)
      for (const SourceScore& score : score_sources(*loops, *truth)) {
        const LoopDetectionScore& c = score.candidates;
        loop_summary->sources.push_back({to_string(score.source),
                                         {{"candidates", double(c.candidates)},
                                          {"precision", c.precision},
                                          {"recall", c.recall},
                                          {"accepted", double(score.accepted)},
                                          {"accepted_wrong", double(score.accepted_wrong)}}});
      }
  }
  write_metrics_json(out / "metrics.json", estimate_accuracy, odometry_accuracy, scans, counts, seconds,
                     loop_summary);
  if (!view.empty())
    write_odometry_view(view, *dataset, o.first, result, poses, truth, map->map(),
                        "sextant odometry: " + meta.name + ", scans " + std::to_string(o.first) + "–" +
                            std::to_string(o.first + scans - 1) + " (" + o.method + ")");
  if (map_output) {
    const PointCloud cloud = map->map().cloud();
    map.reset();  // the voxels' memory, before the writer's copies
    map_output->write(folder, cloud);
  }
  write_file_atomically(out / "provenance.json",
                        provenance_json(o, config, meta, s, result, scans, start, seconds, map_summary));
  folder.commit();

  std::cout << std::fixed << std::setprecision(1) << "registered " << result.steps.size() << " pairs in "
            << seconds << " s (" << std::setprecision(3)
            << (result.steps.empty() ? 0.0 : seconds / static_cast<double>(result.steps.size()))
            << " s per pair), " << counts.not_converged << " not converged, " << counts.untrusted
            << " untrusted"
            << (s.recover ? " (the least suspect registration, the last trusted motion or the guess chained)"
                          : "")
            << ", " << counts.recovered << " recovered\n";
  if (const std::string dropped = dropped_points_line(counts, scans); !dropped.empty())
    std::cout << "dropped:  " << dropped << "\n";
  if (map_summary) {
    std::ostringstream voxel;  // as given, or as chosen: 0.2, 0.05, 0.125
    voxel << map_summary->voxel;
    std::cout << "map:      " << map_summary->points << " points (voxel " << voxel.str() << " m) → "
              << map_output->path().string();
    if (map_summary->scans_left_out > 0)
      std::cout << "; " << map_summary->scans_left_out << " of " << scans
                << " scans left out, placed by untrusted steps (--map-trusted-only)";
    if (map_summary->skipped_points > 0)
      std::cout << "; " << map_summary->skipped_points << " points beyond the voxel index's range left out";
    std::cout << "\n";
  }
  if (loops)
    std::cout << "loops:    " << loops->closing.accepted() << " of " << loops->closing.attempts.size()
              << " candidates closed (" << o.loop_closure << "; " << loops->place_matches
              << " place matches), in " << std::setprecision(1) << loops->seconds << " s\n";
  if (loop_summary)
    for (const auto& [source, numbers] : loop_summary->sources) {
      std::cout << "  " << std::setw(10) << std::left << source << std::right;
      for (const auto& [key, value] : numbers)
        std::cout << " " << key << " " << std::setprecision(key == "precision" || key == "recall" ? 2 : 0)
                  << value;
      std::cout << "\n";
    }
  if (loop_summary && loop_summary->chained)
    std::cout << "chained:  " << accuracy_line(*loop_summary->chained) << " (before closing the loops)\n";
  if (!truth) {
    std::cout << "no ground truth for these scans: no ATE, RPE or drift\n";
  } else if (scans >= 2) {
    std::cout << "estimate: "
              << (estimate_accuracy ? accuracy_line(*estimate_accuracy) : "no accuracy: " + estimate_problem)
              << "\n";
    if (odometry_accuracy || !odometry_problem.empty())
      std::cout << "odometry: "
                << (odometry_accuracy ? accuracy_line(*odometry_accuracy)
                                      : "no accuracy: " + odometry_problem)
                << " (the dataset's)\n";
    if (counts.trusted_off_reference) {
      const std::string off = off_reference_warning(*counts.trusted_off_reference, o.first, result.tolerance);
      if (!off.empty()) std::cout << "check:    " << off << "\n";
    }
  }
  if (verbosity() == Verbosity::kVerbose) print_steps(result, o.first);
  if (!quiet)
    std::cout << "wrote:    " << (folder.target() / "trajectory.tum").string() << ", trajectory.kitti.txt"
              << (truth ? ", groundtruth.tum, groundtruth.kitti.txt" : "")
              << ", steps.csv, metrics.json, provenance.json"
              << (loops ? ", loop_closures.csv, chained/trajectory.tum, chained/trajectory.kitti.txt" : "")
              << "\n";
  if (!quiet && !o.view.empty())
    std::cout << "view:     " << o.view
              << " (the map, the trajectory and the marked steps; open it in a browser)\n";
  return 0;
}

}  // namespace

void add_odometry_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "odometry",
      "Chain registrations over a sequence (a folder of scans, uos, KITTI, a ROS 1/ROS 2 bag "
      "or MCAP recording, or 'campus'), "
      "write the trajectory (TUM, KITTI) and score it against the ground truth");
  auto o = std::make_shared<OdometryOptions>();
  cmd->add_option("dataset", o->dataset,
                  "a folder of scans (.pcd .ply .bin .xyz32.bin .xyz .csv .3d, in it or in scans/, in the "
                  "order of the number in their names; optional poses.txt and times.txt), a uos folder "
                  "(scanNNN.3d + .pose/.frames), a KITTI sequence folder (velodyne/, calib.txt, poses), a "
                  "recording (a ROS 1 .bag, an .mcap file, a ROS 2 bag folder: one scan per "
                  "sensor_msgs/PointCloud2 message), or 'campus' (the built-in synthetic campus)")
      ->required();
  cmd->add_option("--out", o->out, "Output folder")->required();
  cmd->add_option("--poses", o->poses,
                  "Ground truth of a folder of scans: a TUM (8 numbers per line) or KITTI (12) file, one "
                  "pose per scan (default: poses.txt beside the scans, if any)");
  cmd->add_option("--method", o->method, "Matcher (mlndt, fbmlndt, ndt, icp_p2p, icp_p2l, pcl_ndt, ...)")
      ->capture_default_str();
  cmd->add_option("--preset", o->preset, "mlndt/fbmlndt settings: default, thesis, outdoor");
  cmd->add_option("--solver", o->solver, "Solver for the NDT family (newton, lm, ceres)");
  cmd->add_option("--sampling", o->sampling, "Input sampler (all, regular, random, gbs, ...)")
      ->capture_default_str();
  cmd->add_option("--config", o->config, "YAML file with optional 'matcher:' and 'sampler:' settings maps");
  cmd->add_option("--guess", o->guess,
                  "Initial guess: odometry, constant_velocity, identity (default: odometry when the dataset "
                  "has it, else constant_velocity)");
  cmd->add_option("--map", o->map,
                  "Register against a local map of the last scans (local_map) or the previous scan (scan)")
      ->capture_default_str();
  cmd->add_option("--loop-closure", o->loop_closure,
                  "Close the trajectory's loops in a pose graph, with candidates from: proximity (the "
                  "estimate comes back near an earlier pose), descriptor (Scan Context place recognition, "
                  "whatever the drift), or both; every closure is verified by a trusted registration. "
                  "trajectory.* is then the loop-closed one, chained/ the chain, loop_closures.csv the "
                  "candidates");
  add_map_options(*cmd, o->map_out, o->map_voxel, o->map_trusted_only);
  cmd->add_option("--view", o->view,
                  "Write one self-contained HTML page of the run (three.js, offline): the map (the scans "
                  "placed by the trajectory), the trajectory and the ground truth, the untrusted, not "
                  "converged and recovered steps marked; a click on a step shows its time, trust, reason "
                  "and error (docs/odometry.md, \"The view of a run\")");
  cmd->add_option("--local-map-scans", o->local_map_scans, "Scans in the local map")
      ->capture_default_str()
      ->check(whole_number(1));
  cmd->add_option("--min-range", o->min_range, "Drop points closer than this to the sensor [m] (self-hits)")
      ->capture_default_str()
      ->check(finite_number(0.0));
  cmd->add_option("--max-acceleration", o->max_acceleration,
                  "With the constant-velocity guess and scan times: the hardest the platform accelerates or "
                  "brakes [m/s²]; a step farther than that allows from the last step's velocity, held in the "
                  "platform's frame or in the world, is not trusted (0: no check)")
      ->capture_default_str()
      ->check(finite_number(0.0));
  CLI::Option* common_view = cmd->add_flag(
      "--common-view", o->common_view,
      "Register only what both sensors see from the guess (each scan's band of elevations and range): the "
      "default for mlndt, measured better there (docs/matcher_defaults.md, \"Registering only what both "
      "scans can see\")");
  cmd->add_flag("--whole-scans", o->whole_scans,
                "Register the whole scans: the default for every method but mlndt")
      ->excludes(common_view);
  cmd->add_option(
         "--sensor", o->sensor,
         "The lidar: spinning (rings over 360°: the checks of an answer without translation and of "
         "the points above the horizon apply), solid_state (a fixed field of view, no rings: they do "
         "not), or auto (measured: spinning when the first scan covers at least 40 % of the azimuth "
         "circle)")
      ->capture_default_str();
  cmd->add_option("--platform", o->platform,
                  "What carries it, which sets the size of a wrong step: car (1 m or 5°), handheld (0.3 m or "
                  "3°), or auto (the median of the last trusted steps' lengths, between the two)")
      ->capture_default_str();
  cmd->add_option("--topic", o->topic,
                  "A recording's sensor_msgs/PointCloud2 topic (default: its only one; `sextant info REC` "
                  "lists them)");
  cmd->add_option("--start", o->start, "A recording: begin this many seconds after its first message")
      ->capture_default_str()
      ->check(finite_number(0.0));
  cmd->add_option("--duration", o->duration,
                  "A recording: read this many seconds from --start (default: to the end)")
      ->check(finite_number(0.0, true));
  cmd->add_option("--every", o->every, "A recording: take every N-th message of the topic")
      ->capture_default_str()
      ->check(whole_number(1));
  cmd->add_option("--first", o->first, "First scan index")->capture_default_str()->check(whole_number());
  cmd->add_option("--scans", o->scans, "Number of scans (0: to the end)")
      ->capture_default_str()
      ->check(whole_number());
  cmd->add_option("--seed", o->seed, "Seed of the samplers' random choices")
      ->capture_default_str()
      ->check(whole_number());
  cmd->add_option("--campus-seed", o->campus_seed, "Seed of the built-in campus")
      ->capture_default_str()
      ->check(whole_number());
  cmd->add_option("--jobs,-j", o->jobs, "Worker threads (0 = all)")->check(worker_threads());
  cmd->add_flag("--no-progress", o->no_progress, "No progress bar");
  cmd->add_flag("--print-config", o->print_config,
                "Print every matcher and sampler setting this run would use (the defaults included) as YAML, "
                "and exit");
  cmd->add_flag("--no-recover", o->no_recover,
                "Chain every registration as the matcher returns it, a plain loop whose constant velocity "
                "continues the last chained motion; trust is counted, not acted on (default: an untrusted "
                "step is registered again with the wide basin, else the least suspect registration or the "
                "last trusted motion is chained)");
  cmd->add_flag("--no-deskew", o->no_deskew,
                "Register the points where they were measured (default: when the points carry their own "
                "time, a t/time/timestamp/offset_time field, each scan is deskewed: every point moved into "
                "the scan's frame at its stamp by the constant velocity of the motion around it, "
                "docs/odometry.md, \"Scans taken while moving\")");
  cmd->callback([&exit_code, o] { exit_code = guarded([o] { return run_odometry_command(*o); }); });
}

}  // namespace sextant::cli
