// `sextant match <reference> <input> [--method mlndt] [--preset default|thesis|outdoor] [--solver lm]
// [--sampling gbs] [--init x,y,z,a,b,g] [--gt FILE] [--config settings.yaml] [--out aligned.pcd] [--json]`,
// or `sextant match <dataset or recording> --index I J [--topic T]` (scans I and J of it):
// one registration of a pair with any registered matcher, its transform, iterations, time and
// the error against a ground-truth matrix (p_ref = T·p_input). With no options: ML-NDT on a GBS
// sample with the `default` preset, as `sextant odometry` and the library (docs/matcher_defaults.md);
// without --init the wide basin searches around the identity (--no-wide-basin: off). Every result
// is assessed (registration_quality.hpp); with --init an untrusted result is registered again with
// the wide basin. Exit status: 0 trusted, 3 not converged or not trusted (why is printed), 1 bad
// input, 2 a usage error.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <tbb/global_control.h>

#include "commands.hpp"
#include "matcher_options.hpp"
#include "number_options.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/cloud_view.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/register_pair.hpp"
#include "sextant/matchers/registration_quality.hpp"
#include "sextant/matchers/sampler.hpp"
#include "sextant/matchers/yaml.hpp"
#include "sextant/pipeline/dataset_argument.hpp"
#include "sextant/pipeline/json.hpp"
#include "transform_argument.hpp"

namespace sextant::cli {
namespace {

struct MatchOptions : MatcherOptions {
  std::string reference, input;
  std::string init;  ///< "x,y,z,alpha,beta,gamma" [m, deg]
  std::string gt, out;
  std::string view;                ///< an HTML page with both clouds before and after, in 3D
  std::string sensor = "auto";     ///< auto, spinning, solid_state
  std::vector<std::size_t> index;  ///< --index I J: scans I and J of the dataset `reference` names
  std::string topic;               ///< with --index: a recording's PointCloud2 topic
  std::uint64_t seed = 1;
  int jobs = 0;  ///< the registration's threads (0: all cores); the result is the same for any count
  bool json = false;
  bool no_wide_basin = false;
  bool print_config = false;
};

/// Error of a registration against ground truth: E = T_gt⁻¹·T_est (docs/design.md, "Conventions").
struct PoseError {
  double cm = 0.0;
  double deg = 0.0;
};

/// A trusted result more than the trust checks' tolerance (1 m or 5°) from --gt: a wrong registration
/// that passed the checks, or a wrong ground truth (as `sextant odometry`'s `check:` line).
bool trusted_off_truth(const RegistrationResult& r, const PoseError& e) {
  const QualitySettings tolerance;
  return r.quality.trusted() &&
         (e.cm > 100.0 * tolerance.ambiguity_metres || e.deg > tolerance.ambiguity_degrees);
}

std::string fs_name(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

/// The error about `centre` (the registration's, register_pair.hpp): about a point kilometres away
/// a thousandth of a degree would read as metres.
PoseError pose_error(const Eigen::Isometry3d& truth, const Eigen::Isometry3d& estimate,
                     const Eigen::Vector3d& centre) {
  const Eigen::Isometry3d at(Eigen::Translation3d{centre});
  const Eigen::Isometry3d E = inverse(at) * inverse(truth) * estimate * at;
  return {100.0 * translation_norm(E), kDegPerRad * rotation_angle(E)};
}

template <class Matrix>
Json json_matrix(const Matrix& M) {
  Json rows = Json::array();
  for (int i = 0; i < M.rows(); ++i) {
    Json row = Json::array();
    for (int j = 0; j < M.cols(); ++j) row.push_back(json_value(M(i, j)));
    rows.push_back(row);
  }
  return rows;
}

void print_json(const MatchOptions& o, const PairRegistration& registered,
                const ScanLoadReport& reference_load, const ScanLoadReport& input_load,
                const std::string& search, const std::optional<PoseError>& error) {
  const PairMatch& m = registered.match;
  const RegistrationResult& r = m.result;
  const auto text_or_null = [](const std::string& text) { return text.empty() ? Json() : Json(text); };
  const Json j = {
      {"method", o.method},
      {"sampling", o.sampling},
      {"transform", json_matrix(r.T.matrix())},
      {"parameters", {"x_m", "y_m", "z_m", "alpha_rad", "beta_rad", "gamma_rad"}},
      {"centre_m", Json::array({json_value(registered.centre.x()), json_value(registered.centre.y()),
                                json_value(registered.centre.z())})},
      {"hessian", json_matrix(r.H)},
      {"covariance", json_matrix(registration_covariance(r.H))},
      {"matched_fraction",
       json_value(r.input_points ? static_cast<double>(r.matched_points) / static_cast<double>(r.input_points)
                                 : kNaN)},
      {"out", text_or_null(o.out)},
      {"view", text_or_null(o.view)},
      {"converged", r.converged},
      {"termination", to_string(r.why)},
      {"iterations", r.iterations},
      {"seconds", json_value(r.seconds)},
      {"reference_seconds", json_value(m.reference_seconds)},
      {"score", json_value(r.score)},
      {"matched_points", r.matched_points},
      {"input_points", r.input_points},
      {"reference_dropped_non_finite", reference_load.non_finite_dropped},
      {"reference_dropped_no_return", reference_load.no_return_dropped},
      {"input_dropped_non_finite", input_load.non_finite_dropped},
      {"input_dropped_no_return", input_load.no_return_dropped},
      {"kept_fraction", json_value(m.kept_fraction)},
      {"trust", to_string(r.quality.trust)},
      {"trust_reason", r.quality.reason},
      {"overlap", json_value(r.quality.overlap)},
      {"constraint_ratio", json_value(r.quality.constraint_ratio)},
      {"fit_ratio", json_value(r.quality.fit_ratio)},
      {"search", search},
      {"sensor", registered.sensor ? Json(to_string(registered.sensor->kind)) : Json()},
      {"error_cm", error ? json_value(error->cm) : Json()},
      {"error_deg", error ? json_value(error->deg) : Json()},
      {"trusted_off_ground_truth", error ? Json(trusted_off_truth(r, *error)) : Json()}};
  std::cout << json_line(j) << "\n";
}

/// -v: the optimiser's iterations (layer, score, step, matched points).
void print_trace(const RegistrationResult& r) {
  std::cout << "iterations:  layer  score  |Δξ|  matched\n";
  for (const IterationTrace& t : r.trace)
    std::cout << "  " << std::setw(3) << t.iteration << "  " << t.layer << "  " << t.score << "  "
              << t.step_norm << "  " << t.matched_points << "\n";
}

/// "x, y, z" with millimetres.
std::string centre_text(const Eigen::Vector3d& c) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << c.x() << ", " << c.y() << ", " << c.z();
  return out.str();
}

/// "solid_state (measured: the input covers 21 % of the azimuth circle; no horizon check)".
std::string sensor_text(const SensorDetection& sensor, const std::string& declared) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(0) << to_string(sensor.kind)
      << (declared == "auto" ? " (measured: " : " (declared; ") << "the input covers "
      << 100.0 * sensor.azimuth_coverage << " % of the azimuth circle"
      << (sensor.kind == SensorKind::spinning ? ")" : "; no horizon check)");
  return out.str();
}

void print_text(const MatchOptions& o, const MatcherConfig& config, const PairRegistration& registered,
                const std::string& search, const std::optional<PoseError>& error) {
  const PairMatch& m = registered.match;
  const RegistrationResult& r = m.result;
  if (verbosity() == Verbosity::kQuiet) {  // the transform alone, and why it is not trusted
    std::cout << std::setprecision(9);
    for (int i = 0; i < 4; ++i)
      std::cout << r.T.matrix()(i, 0) << " " << r.T.matrix()(i, 1) << " " << r.T.matrix()(i, 2) << " "
                << r.T.matrix()(i, 3) << "\n";
    if (!r.quality.trusted())
      std::cerr << "not trusted: " << to_string(r.quality.trust) << " (" << r.quality.reason << ")\n";
    return;
  }
  const Pose6 p = to_pose6(r.T);
  const std::string trust_note = uncalibrated_trust_note(settings_off_the_defaults(config));
  std::cout << std::fixed << std::setprecision(6) << "method:      " << describe_matcher(config)
            << ", sampling " << o.sampling << ": " << r.input_points << " points (" << std::setprecision(1)
            << 100.0 * m.kept_fraction << "%)\n"
            << std::setprecision(6) << "transform:   (p_reference = T · p_input)\n";
  for (int i = 0; i < 4; ++i) {
    std::cout << "  ";
    for (int j = 0; j < 4; ++j) std::cout << std::setw(12) << r.T.matrix()(i, j);
    std::cout << "\n";
  }
  std::cout << "pose:        x " << p.x << " y " << p.y << " z " << p.z << " m, alpha "
            << p.alpha * kDegPerRad << " beta " << p.beta * kDegPerRad << " gamma " << p.gamma * kDegPerRad
            << " deg\n"
            << "result:      " << r.summary() << "\n"
            << "search:      " << search << "\n"
            << (registered.sensor ? "sensor:      " + sensor_text(*registered.sensor, o.sensor) + "\n" : "")
            << (registered.centre.isZero()
                    ? ""
                    : "centre:      " + centre_text(registered.centre) +
                          " m, the middle of the reference's box: its coordinates lie far "
                          "from their origin, so the registration turned about this point "
                          "(the Hessian, covariance and --gt error are about it)\n")
            << std::setprecision(3) << "trust:       " << to_string(r.quality.trust)
            << (r.quality.reason.empty() ? "" : " (" + r.quality.reason + ")") << "; overlap "
            << r.quality.overlap << ", weakest/strongest constraint " << r.quality.constraint_ratio
            << ", fit " << r.quality.fit_ratio << " x predicted\n"
            << (trust_note.empty() ? "" : "note:        " + trust_note + "\n") << std::setprecision(4)
            << "time:        " << r.seconds << " s registration, " << m.reference_seconds
            << " s reference model, " << m.sampling_seconds << " s sampling\n";
  if (error) std::cout << "error:       " << error->cm << " cm, " << error->deg << " deg (against --gt)\n";
  if (error && trusted_off_truth(r, *error)) {
    const QualitySettings tolerance;
    std::ostringstream limit;  // without the fixed precision of the lines above
    limit << tolerance.ambiguity_metres << " m or " << tolerance.ambiguity_degrees << "°";
    std::cout << "check:       trusted, yet more than " << limit.str()
              << " from --gt: the ground truth or this registration is wrong\n";
  }
  if (verbosity() == Verbosity::kVerbose) print_trace(r);
}

/// The pair: two cloud files, or scans I and J of a dataset or recording (--index); their names for
/// messages, and what reading them dropped.
struct Pair {
  PointCloud reference, input;
  std::string reference_name, input_name;
  ScanLoadReport reference_report, input_report;
};

Pair read_pair(const MatchOptions& o) {
  Pair p;
  if (o.index.empty()) {
    p.reference = read_cloud(o.reference, &p.reference_report);
    p.input = read_cloud(o.input, &p.input_report);
    p.reference_name = o.reference;
    p.input_name = o.input;
    return p;
  }
  RecordingSelection selection;
  selection.topic = o.topic;
  const std::unique_ptr<Dataset> dataset =
      open_dataset_argument(o.reference, std::nullopt, 1, Face::cli, selection);
  for (const std::size_t i : o.index)
    if (i >= dataset->size())
      throw InputError("--index", "",
                       "scan " + std::to_string(i) + " of " + o.reference + ", which has " +
                           std::to_string(dataset->size()) + " scans (0 to " +
                           std::to_string(dataset->size() - 1) + ")");
  p.reference = dataset->scan(o.index[0], &p.reference_report);
  p.input = dataset->scan(o.index[1], &p.input_report);
  p.reference_name = o.reference + " scan " + std::to_string(o.index[0]);
  p.input_name = o.reference + " scan " + std::to_string(o.index[1]);
  return p;
}

int run_match(MatchOptions o) {
  const MatcherConfig config = read_matcher_config(o);
  if (o.print_config) {  // what the first registration runs with: with the wide basin without --init
    std::cout << YAML::Dump(read_matcher_config(o, o.init.empty() && !o.no_wide_basin).resolved) << "\n";
    return 0;
  }
  std::optional<tbb::global_control> threads;
  if (o.jobs > 0)
    threads.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(o.jobs));
  const Eigen::Isometry3d initial = o.init.empty() ? Eigen::Isometry3d::Identity() : parse_init(o.init);
  std::optional<Eigen::Isometry3d> truth;
  if (!o.gt.empty()) truth = read_ground_truth(o.gt);
  const Pair pair = read_pair(o);
  const PointCloud& reference = pair.reference;
  const PointCloud& input = pair.input;
  const ScanLoadReport& reference_report = pair.reference_report;
  const ScanLoadReport& input_report = pair.input_report;
  for (const auto& [file, report] :
       {std::pair{&pair.reference_name, &reference_report}, std::pair{&pair.input_name, &input_report}}) {
    for (const std::string& warning : report->warnings)
      std::cerr << "warning: " << *file << ": " << warning << "\n";
    if (const std::string dropped = dropped_points_note(*report); !dropped.empty())
      std::cerr << "note: " << *file << ": " << dropped << "\n";
  }
  PairRegistrationRequest request;
  request.matcher = matcher_choice(config.spec.matcher);
  request.sampler = sampler_factory(config.spec.sampler);
  if (!o.init.empty()) request.init = initial;
  request.wide_basin = !o.no_wide_basin;
  request.seed = o.seed;
  request.sensor = parse_enum(kSensorKindNames, o.sensor, "--sensor");
  const PairRegistration registered = register_pair(reference, input, request);
  const PairMatch& m = registered.match;
  std::string search = registered.search;
  if (registered.searched_without_guess) search += " (no --init; --no-wide-basin: off)";
  std::optional<PoseError> error;
  if (truth) error = pose_error(*truth, m.result.T, registered.centre);
  if (!o.out.empty()) {
    const CloudWriteReport written = write_cloud(o.out, input.transformed(m.result.T));
    if (const std::string note = dropped_on_reading_note(o.out, written); !note.empty())
      std::cerr << "warning: " << note << "\n";
    if (!o.json && verbosity() != Verbosity::kQuiet)
      std::cout << "wrote:       " << o.out << " (the input in the reference frame)\n";
  }
  if (!o.view.empty()) {
    write_registration_view(o.view, reference, input, initial, m.result.T,
                            (o.index.empty() ? fs_name(o.reference) + " ← " + fs_name(o.input)
                                             : fs_name(o.reference) + ": scan " + std::to_string(o.index[0]) +
                                                   " ← scan " + std::to_string(o.index[1])) +
                                " (" + to_string(m.result.quality.trust) + ")");
    if (!o.json && verbosity() != Verbosity::kQuiet)
      std::cout << "wrote:       " << o.view << " (3D view: before and after; open it in a browser)\n";
  }
  if (o.json) {
    print_json(o, registered, reference_report, input_report, search, error);
  } else {
    print_text(o, config, registered, search, error);
  }
  return m.result.quality.trusted() ? 0 : kExitUntrusted;  // not converged is not trusted either
}

}  // namespace

void add_match_command(CLI::App& app, int& exit_code) {
  auto* cmd =
      app.add_subcommand("match", "Register one pair of scans with any matcher and report the result");
  auto o = std::make_shared<MatchOptions>();
  cmd->add_option("reference", o->reference,
                  "Reference cloud file (.3d .bin .xyz32.bin .pcd .ply .csv ...); with --index, a dataset (a "
                  "folder of scans, uos, KITTI, 'campus') or a recording (.bag, .mcap, a ROS 2 bag folder)")
      ->required();
  cmd->add_option("input", o->input, "Input cloud file, aligned into the reference frame (not with --index)");
  cmd->add_option("--index", o->index,
                  "Register scan J (the input) into scan I (the reference) of the dataset or recording named "
                  "first: --index I J")
      ->expected(2)
      ->check(whole_number());
  cmd->add_option("--topic", o->topic,
                  "With --index: a recording's sensor_msgs/PointCloud2 topic (default: its only one)");
  cmd->add_option("--method", o->method, "Matcher name (mlndt, ndt, icp_p2p, icp_p2l, pcl_ndt, ...)")
      ->capture_default_str();
  cmd->add_option("--preset", o->preset,
                  "mlndt/fbmlndt settings: default (the default: measured best on real scans), thesis (the "
                  "thesis' exact settings), outdoor (6 layers over the bounding box)");
  cmd->add_option("--solver", o->solver, "Solver for the NDT family (newton, lm, ceres)");
  cmd->add_option("--sampling", o->sampling, "Input sampler (all, regular, random, gbs, ...)")
      ->capture_default_str();
  cmd->add_option(
      "--init", o->init,
      "Initial guess (p_reference = T · p_input): x,y,z,alpha,beta,gamma [m, deg]; 12 or 16 numbers "
      "(a 3x4 or 4x4 row-major matrix); or a file holding such a matrix");
  cmd->add_option("--gt", o->gt, "Ground truth: 3x4 or 4x4 matrix text file mapping input into reference");
  cmd->add_option("--config", o->config, "YAML file with optional 'matcher:' and 'sampler:' settings maps");
  cmd->add_option("--out", o->out, "Write the aligned input cloud here (format by extension)");
  cmd->add_option("--view", o->view,
                  "Write a self-contained HTML page showing both clouds before and after the registration in "
                  "3D (rotate, zoom, toggle)");
  cmd->add_option("--seed", o->seed, "Seed of the sampler's random choices")
      ->capture_default_str()
      ->check(whole_number());
  cmd->add_option("--sensor", o->sensor,
                  "The lidar: spinning (a trusted answer is confirmed by the points above the horizon), "
                  "solid_state (no rings: it is not), or auto (spinning when the input covers at least 40 % "
                  "of the azimuth circle)")
      ->capture_default_str();
  cmd->add_option("--jobs,-j", o->jobs,
                  "Threads of the registration (0 = all; the result is the same for any)")
      ->check(worker_threads());
  cmd->add_flag("--print-config", o->print_config,
                "Print every matcher and sampler setting the registration would use (the defaults included) "
                "as YAML, and exit");
  cmd->add_flag(
      "--json", o->json,
      "Print one JSON object instead of text: transform, hessian and covariance (= H⁻¹, eq. 3.50; rows "
      "and columns x y z [m], alpha beta gamma [rad]), trust, matched_fraction, …");
  cmd->add_flag("--no-wide-basin", o->no_wide_basin,
                "Without --init: register from the identity only (default: the wide basin searches "
                "yaw and x/y around it); with --init: no wide-basin retry of an untrusted result");
  cmd->footer(
      "Exit status: 0 the result is trusted; 3 it is not (not converged, low overlap, degenerate, a "
      "poor fit or ambiguous; the reason is printed); 1 bad input; 2 a usage error.");
  cmd->callback([&exit_code, o] {
    if (o->index.empty() && o->input.empty() && !o->print_config) throw CLI::RequiredError("input");
    if (!o->index.empty() && !o->input.empty())
      throw CLI::ValidationError("--index", "takes one dataset, not two cloud files (" + o->input + ")");
    if (!o->topic.empty() && o->index.empty()) throw CLI::ValidationError("--topic", "only with --index");
    exit_code = guarded([o] { return run_match(*o); });
  });
}

}  // namespace sextant::cli
