// `sextant match <reference> <input> [--method mlndt] [--preset default|thesis|outdoor] [--solver lm]
// [--sampling gbs] [--init x,y,z,a,b,g] [--gt FILE] [--config settings.yaml] [--out aligned.pcd] [--json]`:
// one registration of a pair with any registered matcher, its transform, iterations, time and
// the error against a ground-truth matrix (p_ref = T·p_input). With no options: ML-NDT on a GBS
// sample with the `default` preset, as `sextant odometry` and the library (docs/matcher_defaults.md);
// without --init the wide basin searches around the identity (--no-wide-basin: off). Every result
// is assessed (registration_quality.hpp); with --init an untrusted result is registered again with
// the wide basin. Exit status: 0 trusted, 3 not converged or not trusted (why is printed), 1 bad
// input, 2 a usage error.
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "matcher_options.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/core/units.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/mlndt_presets.hpp"
#include "sextant/matchers/sampler.hpp"

namespace sextant::cli {
namespace {

struct MatchOptions : MatcherOptions {
  std::string reference, input;
  std::string init;  ///< "x,y,z,alpha,beta,gamma" [m, deg]
  std::string gt, out;
  std::uint64_t seed = 1;
  bool json = false;
  bool no_wide_basin = false;
};

/// Error of a registration against ground truth: E = T_gt⁻¹·T_est (docs/design.md, "Conventions").
struct PoseError {
  double cm = 0.0;
  double deg = 0.0;
};

/// A guess beyond this is no guess between two scans (PCL's peers abort the process on 1e39) [m].
constexpr double kMaxGuessMetres = 1e6;

Eigen::Isometry3d parse_init(const std::string& text) {
  std::vector<double> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    try {
      std::size_t used = 0;
      values.push_back(std::stod(item, &used));
      if (item.find_first_not_of(" \t", used) != std::string::npos) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError("--init", "",
                       "'" + item + "' is not a number (expected x,y,z,alpha,beta,gamma in m and deg)");
    }
  }
  if (values.size() != 6 || !Eigen::Map<const Vector6d>(values.data()).allFinite())
    throw InputError("--init", "",
                     "expected six finite numbers x,y,z,alpha,beta,gamma (m, deg), got '" + text + "'");
  if (Eigen::Map<const Eigen::Vector3d>(values.data()).norm() > kMaxGuessMetres)
    throw InputError("--init", "",
                     "the translation is farther than 10^6 m (" + text + "): not a guess between two scans");
  return to_isometry(Pose6{values[0], values[1], values[2], values[3] / kDegPerRad, values[4] / kDegPerRad,
                           values[5] / kDegPerRad});
}

/// A 3×4 or 4×4 row-major matrix text file (whitespace separated) mapping input into reference.
Eigen::Isometry3d read_ground_truth(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file, "", "cannot open the ground-truth matrix file");
  std::vector<double> values;
  std::string token;
  while (in >> token) {
    try {
      std::size_t used = 0;
      values.push_back(std::stod(token, &used));
      if (used != token.size()) throw std::invalid_argument(token);
    } catch (const std::exception&) {
      throw InputError(file, "", "'" + token + "' is not a number (expected a 3×4 or 4×4 matrix)");
    }
  }
  if (values.size() != 12 && values.size() != 16)
    throw InputError(file, "",
                     "expected 12 (3×4) or 16 (4×4) numbers, found " + std::to_string(values.size()));
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  for (std::size_t i = 0; i < values.size(); ++i)
    M(static_cast<int>(i / 4), static_cast<int>(i % 4)) = values[i];
  if (const std::string why = rigid_problem(M.topLeftCorner<3, 3>(), M.topRightCorner<3, 1>()); !why.empty())
    throw InputError(file, "", "not a rigid transform: " + why);
  if (!M.allFinite() || !M.row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1)))
    throw InputError(file, "", "the matrix is not finite or its last row is not 0 0 0 1");
  const Eigen::Matrix3d R = M.topLeftCorner<3, 3>();
  if (!(R.transpose() * R).isApprox(Eigen::Matrix3d::Identity(), 1e-4) || R.determinant() < 0.0)
    throw InputError(file, "", "the rotation part is not a rotation matrix");
  Eigen::Isometry3d T;
  T.matrix() = M;
  return T;
}

PoseError pose_error(const Eigen::Isometry3d& truth, const Eigen::Isometry3d& estimate) {
  const Eigen::Isometry3d E = inverse(truth) * estimate;
  return {100.0 * translation_norm(E), kDegPerRad * rotation_angle(E)};
}

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream out;
  out << std::setprecision(12) << v;
  return out.str();
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

void print_json(const MatchOptions& o, const PairMatch& m, const std::string& search,
                const std::optional<PoseError>& error) {
  const RegistrationResult& r = m.result;
  std::ostringstream out;
  out << "{\"method\": " << json_string(o.method) << ", \"sampling\": " << json_string(o.sampling)
      << ", \"transform\": [";
  for (int i = 0; i < 4; ++i) {
    out << (i ? ", [" : "[");
    for (int j = 0; j < 4; ++j) out << (j ? ", " : "") << json_number(r.T.matrix()(i, j));
    out << "]";
  }
  out << "], \"converged\": " << (r.converged ? "true" : "false")
      << ", \"termination\": " << json_string(to_string(r.why)) << ", \"iterations\": " << r.iterations
      << ", \"seconds\": " << json_number(r.seconds)
      << ", \"reference_seconds\": " << json_number(m.reference_seconds)
      << ", \"score\": " << json_number(r.score) << ", \"matched_points\": " << r.matched_points
      << ", \"input_points\": " << r.input_points << ", \"kept_fraction\": " << json_number(m.kept_fraction)
      << ", \"trust\": " << json_string(to_string(r.quality.trust))
      << ", \"trust_reason\": " << json_string(r.quality.reason)
      << ", \"overlap\": " << json_number(r.quality.overlap)
      << ", \"constraint_ratio\": " << json_number(r.quality.constraint_ratio)
      << ", \"fit_ratio\": " << json_number(r.quality.fit_ratio) << ", \"search\": " << json_string(search)
      << ", \"error_cm\": " << (error ? json_number(error->cm) : "null")
      << ", \"error_deg\": " << (error ? json_number(error->deg) : "null") << "}\n";
  std::cout << out.str();
}

void print_text(const MatchOptions& o, const PairMatch& m, const std::string& search,
                const std::optional<PoseError>& error) {
  const RegistrationResult& r = m.result;
  const Pose6 p = to_pose6(r.T);
  std::cout << std::fixed << std::setprecision(6) << "method:      " << describe_matcher(o) << ", sampling "
            << o.sampling << ": " << r.input_points << " points (" << std::setprecision(1)
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
            << std::setprecision(3) << "trust:       " << to_string(r.quality.trust)
            << (r.quality.reason.empty() ? "" : " (" + r.quality.reason + ")") << "; overlap "
            << r.quality.overlap << ", weakest/strongest constraint " << r.quality.constraint_ratio
            << ", fit " << r.quality.fit_ratio << " x predicted\n"
            << std::setprecision(4) << "time:        " << r.seconds << " s registration, "
            << m.reference_seconds << " s reference model, " << m.sampling_seconds << " s sampling\n";
  if (error) std::cout << "error:       " << error->cm << " cm, " << error->deg << " deg (against --gt)\n";
}

int run_match(MatchOptions o) {
  const PointCloud reference = read_cloud(o.reference);
  const MatcherConfig config = read_matcher_config(o);
  const std::string where = o.config.empty() ? "matcher settings (--solver)" : o.config;
  const auto sampler =
      make_sampler(o.sampling, config.sampler, o.config.empty() ? "sampler settings" : o.config);
  const Eigen::Isometry3d initial = o.init.empty() ? Eigen::Isometry3d::Identity() : parse_init(o.init);
  std::optional<Eigen::Isometry3d> truth;
  if (!o.gt.empty()) truth = read_ground_truth(o.gt);
  const PointCloud input = read_cloud(o.input);
  // Without a guess the wide basin searches around the identity; with one, the guess is refined and
  // the wide basin is the recovery of an untrusted result.
  const std::optional<YAML::Node> wide = with_wide_basin(o.method, config.matcher);
  const bool has_own_wide_basin = config.matcher.IsMap() && config.matcher["wide_basin"].IsDefined();
  const bool search_first = o.init.empty() && !o.no_wide_basin && wide.has_value();
  auto matcher = make_matcher(o.method, search_first ? *wide : config.matcher, where);
  Rng rng(o.seed);
  PairMatch m = match_pair(*matcher, *sampler, reference, input, initial, rng);
  const bool searched = has_own_wide_basin || search_first;  // the first registration was the wide basin
  std::string search = searched ? "wide basin" : "from the guess";
  if (search_first) search += " (no --init; --no-wide-basin: off)";
  if (!m.result.quality.trusted() && !searched && !o.no_wide_basin && wide) {
    const auto wide_matcher = make_matcher(o.method, *wide, where);
    Rng again(o.seed);
    PairMatch w = match_pair(*wide_matcher, *sampler, reference, input, initial, again);
    const std::string first = to_string(m.result.quality.trust);
    if (w.result.quality.trusted()) {
      m = std::move(w);
      search += ", " + first + ": recovered by the wide basin";
    } else {
      search += ", " + first + ": the wide basin found no trusted pose either";
    }
  }
  std::optional<PoseError> error;
  if (truth) error = pose_error(*truth, m.result.T);
  if (!o.out.empty()) {
    write_cloud(o.out, input.transformed(m.result.T));
    if (!o.json) std::cout << "wrote:       " << o.out << " (the input in the reference frame)\n";
  }
  if (o.json) {
    print_json(o, m, search, error);
  } else {
    print_text(o, m, search, error);
  }
  return m.result.quality.trusted() ? 0 : kExitUntrusted;  // not converged is not trusted either
}

}  // namespace

void add_match_command(CLI::App& app, int& exit_code) {
  auto* cmd =
      app.add_subcommand("match", "Register one pair of scans with any matcher and report the result");
  auto o = std::make_shared<MatchOptions>();
  cmd->add_option("reference", o->reference, "Reference cloud file (.3d .bin .xyz32.bin .pcd .ply .csv ...)")
      ->required();
  cmd->add_option("input", o->input, "Input cloud file, aligned into the reference frame")->required();
  cmd->add_option("--method", o->method, "Matcher name (mlndt, ndt, icp_p2p, icp_p2l, pcl_ndt, ...)")
      ->capture_default_str();
  cmd->add_option("--preset", o->preset,
                  "mlndt/fbmlndt settings: default (the default: measured best on real scans), thesis (the "
                  "thesis' exact settings), outdoor (6 layers over the bounding box)");
  cmd->add_option("--solver", o->solver, "Solver for the NDT family (newton, lm, ceres)");
  cmd->add_option("--sampling", o->sampling, "Input sampler (all, regular, random, gbs, ...)")
      ->capture_default_str();
  cmd->add_option("--init", o->init, "Initial guess x,y,z,alpha,beta,gamma [m, deg]");
  cmd->add_option("--gt", o->gt, "Ground truth: 3x4 or 4x4 matrix text file mapping input into reference");
  cmd->add_option("--config", o->config, "YAML file with optional 'matcher:' and 'sampler:' settings maps");
  cmd->add_option("--out", o->out, "Write the aligned input cloud here (format by extension)");
  cmd->add_option("--seed", o->seed, "Seed of the sampler's random choices")->capture_default_str();
  cmd->add_flag("--json", o->json, "Print one JSON object instead of text");
  cmd->add_flag("--no-wide-basin", o->no_wide_basin,
                "Without --init: register from the identity only (default: the wide basin searches "
                "yaw and x/y around it); with --init: no wide-basin retry of an untrusted result");
  cmd->footer(
      "Exit status: 0 the result is trusted; 3 it is not (not converged, low overlap, degenerate or a "
      "poor fit; the reason is printed); 1 bad input; 2 a usage error.");
  cmd->callback([&exit_code, o] { exit_code = guarded([o] { return run_match(*o); }); });
}

}  // namespace sextant::cli
