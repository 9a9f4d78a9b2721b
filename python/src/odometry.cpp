// sextant.odometry(): run_odometry (odometry.hpp) over a dataset folder, the built-in campus or a
// list of arrays, with `sextant odometry`'s defaults (cmd_odometry.cpp), and its OdometryRun: the
// poses, the per-step table with the columns of the CLI's steps.csv, the Hessians, and with
// build_map=True the run's map (run_map_builder.hpp, what --map-out writes).
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include <oneapi/tbb/global_control.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "match_request.hpp"
#include "odometry_dataset.hpp"
#include "python_yaml.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/threads.hpp"
#include "sextant/matchers/matcher_choice.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/pipeline/matcher_request.hpp"
#include "sextant/pipeline/odometry_output.hpp"
#include "sextant/pipeline/odometry_request.hpp"
#include "sextant/pipeline/odometry_view.hpp"
#include "sextant/pipeline/run_map_builder.hpp"
#include "steps_table.hpp"

namespace sextant::python {
namespace {

/// What sextant.odometry() returns (see the docstrings in bind_odometry).
struct OdometryRun {
  py::object poses, relative, hessians, ground_truth, steps, dataset;
  std::string guess, map;
  std::string deskew;  ///< "constant_velocity" or "off"
  std::size_t timed_scans = 0, deskewed = 0;
  std::string sensor;        ///< the lidar the checks assumed (declared, or measured)
  double tolerance_m = 0.0;  ///< the size of a wrong step the run ended with (platform_tolerance)
  std::size_t first = 0, scans = 0, not_converged = 0, untrusted = 0, recovered = 0;
  std::size_t points_read = 0, dropped_non_finite = 0, dropped_no_return = 0;
  double seconds = 0.0;
  /// With build_map: the map's points (N×3 float32), intensity (N float32, or None) and voxel [m];
  /// None without.
  py::object map_points = py::none(), map_intensity = py::none(), map_voxel = py::none();
  std::size_t map_scans_left_out = 0;
};

/// The map settings of odometry()'s arguments; InputError / ValueError naming the argument.
std::optional<RunMapSettings> map_settings(bool build_map, const py::object& map_voxel, bool trusted_only) {
  if (!build_map) {
    if (!map_voxel.is_none()) throw py::value_error("map_voxel: a map's voxel needs build_map=True");
    if (trusted_only) throw py::value_error("map_trusted_only: needs build_map=True");
    return std::nullopt;
  }
  RunMapSettings settings;
  settings.trusted_only = trusted_only;
  if (!map_voxel.is_none()) {
    const double voxel = map_voxel.cast<double>();
    if (const std::string problem = map_voxel_problem(voxel); !problem.empty())
      throw InputError("arguments", "", "map_voxel " + problem);
    settings.voxel = voxel;
  }
  return settings;
}

py::dict metadata_dict(const DatasetMetadata& m) {
  py::dict d;
  d["name"] = m.name;
  d["format"] = m.format;
  d["path"] = m.path.string();
  d["scans"] = m.scan_count;
  d["has_odometry"] = m.has_odometry;
  d["has_ground_truth"] = m.has_ground_truth;
  d["notes"] = py::cast(m.notes);
  return d;
}

OdometryRun odometry(const py::object& source, const std::string& method, const py::object& preset,
                     const std::string& sampling, const py::object& guess, const std::string& map,
                     std::size_t first, std::size_t scans, std::size_t local_map_scans, double min_range,
                     double max_acceleration, std::uint64_t seed, bool recover, const py::object& common_view,
                     const py::object& poses, const py::object& odometry_poses, const py::object& times,
                     std::uint64_t campus_seed, int jobs, const py::object& sampler_settings,
                     const std::string& sensor, const std::string& platform, bool build_map,
                     const py::object& map_voxel, bool map_trusted_only, const py::object& view,
                     const py::object& topic, double start, const py::object& duration, std::size_t every,
                     bool deskew, const py::kwargs& settings) {
  // Arguments first (cheap), then the dataset, as the CLI (odometry_request.hpp).
  const MatcherConfig config =  // unknown names, bad settings
      read_matcher_config(matcher_request("odometry()", method, preset, sampling, settings, sampler_settings),
                          Face::python);
  OdometryRequest request;
  request.method = method;
  request.registration = {matcher_choice(config.spec.matcher), sampler_factory(config.spec.sampler)};
  if (!guess.is_none()) request.guess = guess.cast<std::string>();
  request.map = map;
  request.sensor = sensor;
  request.platform = platform;
  if (!common_view.is_none()) request.common_view = common_view.cast<bool>();
  request.first = first;
  request.scans = scans;
  request.local_map_scans = local_map_scans;
  request.min_range = min_range;
  request.max_acceleration = max_acceleration;
  request.seed = seed;
  request.recover = recover;
  request.deskew = deskew;
  OdometrySettings checked = odometry_settings(request, Face::python);
  if (const std::string problem = worker_threads_problem(jobs, "jobs"); !problem.empty())
    throw py::value_error(problem);
  const std::optional<RunMapSettings> world_map = map_settings(build_map, map_voxel, map_trusted_only);
  const std::string view_path =
      view.is_none() ? std::string() : py::module_::import("os").attr("fspath")(view).cast<std::string>();
  if (!view_path.empty()) check_run_view_path(view_path);  // before the run, not after it

  RecordingSelection selection;
  if (!topic.is_none()) selection.topic = topic.cast<std::string>();
  selection.start = start;
  if (!duration.is_none()) selection.duration = duration.cast<double>();
  selection.every = every;
  const std::unique_ptr<Dataset> dataset =
      open_odometry_dataset(source, poses, odometry_poses, times, campus_seed, selection);
  const DatasetMetadata& meta = dataset->metadata();
  const OdometryPlan plan = plan_odometry(std::move(checked), request, *dataset,
                                          meta.path.empty() ? meta.name : meta.path.string(), Face::python);
  const OdometrySettings& s = plan.settings;
  const std::size_t count = plan.scans;

  OdometryResult result;
  std::optional<std::vector<Eigen::Isometry3d>> truth;
  std::optional<RunMapBuilder> builder;  // built as the run goes, as the CLI's --map-out; the view draws it
  if (world_map || !view_path.empty()) builder.emplace(world_map.value_or(RunMapSettings{}));
  double seconds = 0.0;
  {
    const py::gil_scoped_release release;
    std::optional<tbb::global_control> threads;
    if (jobs > 0)
      threads.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(jobs));
    const auto t0 = std::chrono::steady_clock::now();
    result =
        run_odometry(*dataset, s, first, count, {}, builder ? builder->observer() : OdometryScanObserver{});
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    truth = ground_truth_of(*dataset, first, count);
    if (!view_path.empty())
      write_odometry_view(view_path, *dataset, first, result, result.poses, truth, builder->map(),
                          "sextant.odometry: " + meta.name + ", scans " + std::to_string(first) + "–" +
                              std::to_string(first + count - 1) + " (" + method + ")");
  }

  OdometryRun run;
  run.poses = poses_array(result.poses);
  std::vector<Eigen::Isometry3d> relative;
  for (const OdometryStep& step : result.steps) relative.push_back(step.relative);
  run.relative = poses_array(relative);
  py::array_t<double> hessians(
      {static_cast<py::ssize_t>(result.steps.size()), py::ssize_t{6}, py::ssize_t{6}});
  auto h = hessians.mutable_unchecked<3>();
  for (std::size_t k = 0; k < result.steps.size(); ++k)
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) h(static_cast<py::ssize_t>(k), i, j) = result.steps[k].hessian(i, j);
  run.hessians = std::move(hessians);
  run.ground_truth = truth ? py::object(poses_array(*truth)) : py::object(py::none());
  run.steps = steps_columns(result, first, truth);
  run.dataset = metadata_dict(meta);
  run.guess = to_string(s.guess);
  run.map = to_string(s.map);
  run.deskew = deskew_scheme(s);
  run.timed_scans = result.timed_scans;
  run.deskewed = result.deskewed();
  run.sensor = to_string(result.sensor.kind);
  run.tolerance_m = result.tolerance.ambiguity_metres;
  run.first = first;
  run.scans = count;
  const OdometryCounts counts = odometry_counts(result);
  run.not_converged = counts.not_converged;
  run.untrusted = counts.untrusted;
  run.recovered = counts.recovered;
  run.points_read = counts.read.points_read;
  run.dropped_non_finite = counts.read.non_finite_dropped;
  run.dropped_no_return = counts.read.no_return_dropped;
  run.seconds = seconds;
  if (world_map) {
    CloudArrays arrays = cloud_arrays(builder->map().cloud());
    run.map_points = std::move(arrays.points);
    run.map_intensity = std::move(arrays.intensity);
    run.map_voxel = py::float_(builder->map().voxel_size());
    run.map_scans_left_out = builder->summary().scans_left_out;
  }
  return run;
}

constexpr char kOdometryDoc[] = R"doc(Chain registrations over a sequence, as ``sextant odometry`` does.

dataset: a folder (a folder of scans with optional poses.txt/times.txt, a uos folder, a KITTI
    sequence folder; opened by the library's open_dataset), a recording (a ROS 1 .bag, an .mcap file, a
    ROS 2 bag folder: one scan per sensor_msgs/PointCloud2 message), "campus" (the built-in synthetic
    campus, seed campus_seed), or a list of scans (N×3/N×4 float32/float64 arrays or file paths) held
    in memory.
topic, start, duration, every: a recording's scans (the CLI's --topic, --start, --duration, --every):
    the sensor_msgs/PointCloud2 topic (None: its only one), from start seconds after its first message
    for duration seconds (None: to the end), every N-th message.
method, preset, sampling, sampler_settings, **settings: the matcher and sampler, as for match()
    (mlndt with preset "default" and GBS by default).
guess: where each registration starts: "odometry", "constant_velocity", "identity"; None: odometry
    when the dataset has it, else constant_velocity (the CLI's default).
map: "local_map" (the default: the last local_map_scans scans) or "scan" (the previous scan).
first, scans: the scans first … first + scans − 1 (scans = 0: to the end).
min_range: drop points closer than this to the sensor [m]. max_acceleration: with the constant-velocity
    guess and times, the hardest the platform accelerates or brakes [m/s²] (a step farther than that
    allows from the last step's velocity, held in the platform's frame or in the world, is not
    trusted; 0: no check). seed: sampler seed (per-step seeds derive
    from it). recover: an untrusted step is registered again with the wide basin (the CLI's default;
    False = --no-recover). common_view: register only what both sensors see from the guess (True,
    --common-view) or the whole scans (False, --whole-scans); None: the CLI's default (True for
    mlndt). jobs: worker threads (0: all cores).
sensor: "spinning", "solid_state" or "auto" (the CLI's --sensor: the ring and horizon checks apply to a
    spinning lidar only; auto measures the first scan). platform: "car", "handheld" or "auto" (the CLI's
    --platform: the size of a wrong step, 1 m or 5°, 0.3 m or 3°, or the typical step's between them).
build_map: also build the run's map, as ``sextant odometry --map-out`` does: every scan (as registered:
    its sensor frame, without min_range's points) moved into the world by its pose and voxel-filtered,
    one point per occupied voxel at the centroid of its points (the mean intensity when every scan has
    it), built as the run goes (memory grows with the occupied voxels, not with the scans); returned as
    OdometryRun.map_points. map_voxel: its voxel edge [m]; None: 1/100 of the first scan's median range,
    rounded to 1, 2 or 5 × 10ⁿ, at least 0.01 (the CLI's --map-voxel). map_trusted_only: leave the scans
    placed by untrusted steps out (the CLI's --map-trusted-only; by default they go in, so that the map
    shows where the run went wrong).
view: a file name (str or path): also write the run's view there, one offline HTML page (the CLI's
    --view: the map, the trajectory and the ground truth, the untrusted, not converged and recovered
    steps marked, a click on a step shows its trust and reason).
deskew: when the points carry their own time (a t, time, timestamp or offset_time field), move each into
    its scan's frame at the scan's stamp by the constant velocity of the motion around it, before the scan
    is registered and kept in the local map (the default, the CLI's; False = --no-deskew).
poses: ground truth. For a folder of scans: a TUM or KITTI file (the CLI's --poses); for a list: an
    N×4×4 array (world ← scan). odometry_poses (N×4×4) and times (N seconds): a list's odometry and
    clock.

Returns an OdometryRun; its poses are those ``sextant odometry`` writes to trajectory.tum (world ←
scan, starting at the first scan's ground truth, else odometry, else the identity) and its steps
table holds the columns of steps.csv. Raises InputError for bad folders, files, names or settings.)doc";

}  // namespace

void bind_odometry(py::module_& m) {
  py::class_<OdometryRun>(m, "OdometryRun", "The result of odometry(): poses, per-step table, Hessians.")
      .def_readonly("poses", &OdometryRun::poses,
                    "N×4×4 float64 world ← scan poses of scans first … first+N−1")
      .def_readonly("relative", &OdometryRun::relative,
                    "(N−1)×4×4 relative poses: relative[i] maps scan first+i+1 into scan first+i")
      .def_readonly("hessians", &OdometryRun::hessians,
                    "(N−1)×6×6 matcher Hessians over (x, y, z, alpha, beta, gamma) of relative[i] "
                    "(see MatchResult.H); R = H⁻¹, eq. 3.50")
      .def_readonly("ground_truth", &OdometryRun::ground_truth,
                    "N×4×4 ground-truth poses of the same scans, or None when any lacks one")
      .def_readonly("steps", &OdometryRun::steps,
                    "dict of NumPy columns, one row per registration, the columns of the CLI's steps.csv: "
                    "step, from_scan, to_scan, x_m, y_m, z_m, roll_deg, pitch_deg, yaw_deg (the relative "
                    "pose; roll/pitch/yaw are alpha/beta/gamma), guess_x_m, guess_y_m, guess_yaw_deg, "
                    "converged, iterations, score, matched_points, reference_points, seconds, error_m, "
                    "error_deg (against the ground truth; NaN without), status, trust, first_trust, "
                    "recovery, overlap, constraint_ratio, fit_ratio, trust_reason, fallback, then the first "
                    "registration's own pose and error before any recovery replaced it: first_x_m … "
                    "first_yaw_deg, first_error_m, first_error_deg")
      .def_readonly(
          "dataset", &OdometryRun::dataset,
          "the dataset's metadata: name, format, path, scans, has_odometry, has_ground_truth, notes")
      .def_readonly("guess", &OdometryRun::guess, "the guess mode used")
      .def_readonly("map", &OdometryRun::map, "the map mode used")
      .def_readonly(
          "deskew", &OdometryRun::deskew,
          "'constant_velocity' (scans whose points carry time were deskewed) or 'off' (deskew=False)")
      .def_readonly("timed_scans", &OdometryRun::timed_scans, "scans whose points carry their own time")
      .def_readonly("deskewed", &OdometryRun::deskewed,
                    "scans deskewed by a known motion (with constant velocity, not the first: no motion is "
                    "known before it)")
      .def_readonly("sensor", &OdometryRun::sensor,
                    "the lidar the checks assumed: 'spinning' or 'solid_state' (declared, or measured on the "
                    "first scan)")
      .def_readonly(
          "tolerance_m", &OdometryRun::tolerance_m,
          "a step more than this from the truth is wrong (the platform's size of a wrong step at the "
          "end of the run) [m]")
      .def_readonly("first", &OdometryRun::first, "the first scan's index")
      .def_readonly("scans", &OdometryRun::scans, "number of scans (poses)")
      .def_readonly("not_converged", &OdometryRun::not_converged, "steps whose registration did not converge")
      .def_readonly("untrusted", &OdometryRun::untrusted, "steps whose chained motion is not trusted")
      .def_readonly("recovered", &OdometryRun::recovered, "steps the wide basin (or a restart) recovered")
      .def_readonly("points_read", &OdometryRun::points_read, "points read from the scans' files")
      .def_readonly("dropped_non_finite", &OdometryRun::dropped_non_finite,
                    "points dropped for a NaN/Inf coordinate (per scan: steps['dropped_non_finite'])")
      .def_readonly(
          "dropped_no_return", &OdometryRun::dropped_no_return,
          "points dropped as the scanner's 'no return' (uos .3d; per scan: steps['dropped_no_return'])")
      .def_readonly("seconds", &OdometryRun::seconds, "wall time of the registrations [s]")
      .def_readonly("map_points", &OdometryRun::map_points,
                    "with build_map=True: the run's map, N×3 float32 world points (one per occupied voxel, "
                    "the centroid of its points, in the order the voxels were first hit); else None")
      .def_readonly("map_intensity", &OdometryRun::map_intensity,
                    "with build_map=True and scans that all have intensity: the N map points' mean "
                    "intensity (float32); else None")
      .def_readonly("map_voxel", &OdometryRun::map_voxel,
                    "with build_map=True: the map's voxel edge [m], given or chosen; else None")
      .def_readonly("map_scans_left_out", &OdometryRun::map_scans_left_out,
                    "with map_trusted_only=True: the scans left out of the map, placed by untrusted steps")
      .def("__repr__", [](const OdometryRun& r) {
        return "OdometryRun(scans=" + std::to_string(r.scans) + ", first=" + std::to_string(r.first) +
               ", guess='" + r.guess + "', untrusted=" + std::to_string(r.untrusted) + ")";
      });
  m.def("odometry", &odometry, kOdometryDoc, py::arg("dataset"), py::arg("method") = "mlndt",
        py::arg("preset") = py::none(), py::arg("sampling") = "gbs", py::arg("guess") = py::none(),
        py::arg("map") = "local_map", py::arg("first") = 0, py::arg("scans") = 0,
        py::arg("local_map_scans") = 5, py::arg("min_range") = 0.0,
        py::arg("max_acceleration") = OdometrySettings{}.max_acceleration, py::arg("seed") = 1,
        py::arg("recover") = true, py::arg("common_view") = py::none(), py::arg("poses") = py::none(),
        py::arg("odometry_poses") = py::none(), py::arg("times") = py::none(), py::arg("campus_seed") = 1,
        py::arg("jobs") = 0, py::arg("sampler_settings") = py::none(), py::arg("sensor") = "auto",
        py::arg("platform") = "auto", py::arg("build_map") = false, py::arg("map_voxel") = py::none(),
        py::arg("map_trusted_only") = false, py::arg("view") = py::none(), py::arg("topic") = py::none(),
        py::arg("start") = 0.0, py::arg("duration") = py::none(), py::arg("every") = 1,
        py::arg("deskew") = true);
}

}  // namespace sextant::python
