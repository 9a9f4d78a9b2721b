#include "pose_graph/params.hpp"

#include <cmath>

#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/sampler.hpp"
#include "sextant/matchers/yaml.hpp"
#include "sextant/posegraph/yaml.hpp"

namespace sextant {
namespace {

std::size_t read_count(SettingsReader& in, const std::string& key, std::size_t fallback, long minimum) {
  long value = static_cast<long>(fallback);
  in.read(key, value);
  if (value < minimum) in.fail(key, "key '" + key + "' must be ≥ " + std::to_string(minimum));
  return static_cast<std::size_t>(value);
}

double read_positive(SettingsReader& in, const std::string& key, double fallback) {
  double value = fallback;
  in.read(key, value);
  if (!(value > 0.0) || !std::isfinite(value)) in.fail(key, "key '" + key + "' must be a positive number");
  return value;
}

}  // namespace

PoseGraphParams read_pose_graph_params(const ExperimentConfig& config) {
  SettingsReader in(config.params, config.file);
  PoseGraphParams p;
  p.scans = read_count(in, "scans", 0, 0);
  std::string odometry = "resample", guess = "odometry";
  in.read("odometry", odometry);
  if (odometry == "campus")
    p.odometry = OdometrySource::kCampus;
  else if (odometry != "resample")
    in.fail("odometry", "key 'odometry': '" + odometry + "' is not campus or resample");
  if (in.read("guess", guess)) {
    try {
      p.guess = parse_enum(kOdometryGuessNames, guess, "key 'guess'");
    } catch (const InputError& e) {
      in.fail("guess", e.what());
    }
  }
  if (in.has("loop_closure"))
    p.loop_closure = read_loop_closure_settings(in.child("loop_closure"), config.file);
  p.closure_rounds = read_count(in, "closure_rounds", p.closure_rounds, 1);
  in.read("calibrate_information", p.calibrate_information);
  if (in.has("graph")) p.graph = read_pose_graph_settings(in.child("graph"), config.file);
  p.false_closures = read_count(in, "false_closures", p.false_closures, 0);
  p.false_closure_min_distance =
      read_positive(in, "false_closure_min_distance", p.false_closure_min_distance);
  p.batch_scans = read_count(in, "batch_scans", p.batch_scans, 1);
  p.false_closure_tolerance_m = read_positive(in, "false_closure_tolerance_m", p.false_closure_tolerance_m);
  p.solve_budget = read_positive(in, "solve_budget", p.solve_budget);
  ExperimentConfig filters = config;
  // reset(), not =: assigning to a YAML::Node writes through to the node it refers to (config.params).
  filters.params.reset(in.has("filters") ? in.child("filters") : YAML::Node());
  in.finish();
  p.filters = read_plane_slam_params(filters);
  if (p.filters.scans != 0)
    in.fail("filters",
            "key 'filters': give the scans once, in params.scans (a filter method may say scans:)");
  p.filters.scans = p.scans;
  std::string why;
  if (!p.filters.valid(&why)) in.fail("filters", why);
  return p;
}

std::vector<PoseGraphMethod> read_pose_graph_methods(const ExperimentConfig& config) {
  std::vector<PoseGraphMethod> out;
  for (const MethodConfig& m : config.methods) {
    PoseGraphMethod method;
    method.name = m.name;
    if (m.node["filter"]) {
      method.is_filter = true;
      method.filter = read_plane_slam_method(m.node, config.file);
    } else {
      SettingsReader in(m.node, config.file);
      std::string name, matcher, sampler = "gbs";
      in.read("name", name);
      in.require("matcher", matcher);
      in.read("sampler", sampler);
      const YAML::Node settings = in.child("settings");
      const YAML::Node sampler_settings = in.child("sampler_settings");
      const YAML::Node closure_settings =
          in.has("closure_settings") ? in.child("closure_settings") : settings;
      in.finish();
      method.odometry.matcher = read_matcher_spec(matcher, settings, config.file);
      method.odometry.sampler = read_sampler_spec(sampler, sampler_settings, config.file);
      method.closure = read_matcher_spec(matcher, closure_settings, config.file);
    }
    out.push_back(std::move(method));
  }
  return out;
}

}  // namespace sextant
