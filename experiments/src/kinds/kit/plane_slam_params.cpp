#include "kit/plane_slam_params.hpp"

#include <cmath>

#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/core/units.hpp"
#include "sextant/filters/plane_slam_model.hpp"
#include "sextant/filters/yaml.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/yaml.hpp"
#include "sextant/synth/yaml.hpp"

namespace sextant {
namespace {

template <class Enum>
Enum read_choice(SettingsReader& in, const std::string& key, Enum fallback,
                 const std::vector<std::pair<std::string, Enum>>& choices) {
  std::string text;
  if (!in.read(key, text)) return fallback;
  std::string names;
  for (const auto& [name, value] : choices) {
    if (name == text) return value;
    names += (names.empty() ? "" : ", ") + name;
  }
  in.fail(key, "key '" + key + "': '" + text + "' is not one of " + names);
}

std::size_t read_count(SettingsReader& in, const std::string& key, std::size_t fallback) {
  long value = static_cast<long>(fallback);
  in.read(key, value);
  if (value < 0) in.fail(key, "key '" + key + "' must be ≥ 0");
  return static_cast<std::size_t>(value);
}

HybridParams read_hybrid_params(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  HybridParams h;
  double alarm_deg = h.alarm_rotation / kRadPerDeg;
  in.read("noise_scale", h.noise_scale);
  in.read("alarm_translation", h.alarm_translation);
  in.read("alarm_rotation_deg", alarm_deg);
  in.read("max_extra_cost", h.max_extra_cost);
  long block = static_cast<long>(h.block);
  in.read("block", block);
  in.finish();
  if (block < 1) in.fail("block", "key 'block' must be ≥ 1");
  h.block = static_cast<std::size_t>(block);
  if (!(h.max_extra_cost > 0.0)) in.fail("max_extra_cost", "key 'max_extra_cost' must be > 0");
  h.alarm_rotation = alarm_deg * kRadPerDeg;
  if (!(h.noise_scale > 0.0)) in.fail("noise_scale", "key 'noise_scale' must be > 0");
  if (!(h.alarm_translation > 0.0 && h.alarm_rotation > 0.0))
    in.fail("alarm_translation", "keys 'alarm_translation' and 'alarm_rotation_deg' must be > 0");
  return h;
}

}  // namespace

bool PlaneSlamParams::valid(std::string* why) const {
  const auto fail = [why](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (landmarks == LandmarkSource::kTrue && min_points < 1) return fail("key 'min_points' must be ≥ 1");
  if (!(nees_probability > 0.0 && nees_probability < 1.0))
    return fail("key 'nees_probability' must lie in (0, 1)");
  if (!(revisit_radius > 0.0)) return fail("key 'revisit_radius' must be > 0");
  if (!(spike_threshold > 0.0)) return fail("key 'spike_threshold' must be > 0");
  if (ellipse_every < 1) return fail("key 'ellipse_every' must be ≥ 1");
  if (claims && !claims.IsNull() && !claims.IsSequence()) return fail("key 'claims' must be a list");
  return true;
}

PlaneSlamParams read_plane_slam_params(const ExperimentConfig& config) {
  SettingsReader in(config.params, config.file);
  PlaneSlamParams p;
  p.landmarks = read_choice<LandmarkSource>(
      in, "landmarks", LandmarkSource::kTrue,
      {{"true", LandmarkSource::kTrue}, {"extracted", LandmarkSource::kExtracted}});
  p.odometry = read_choice<OdometrySource>(
      in, "odometry", OdometrySource::kCampus,
      {{"campus", OdometrySource::kCampus}, {"resample", OdometrySource::kResample}});
  in.read("report", p.report);  // a name of plane_slam/layouts/layouts.cpp, checked by that kind
  p.scans = read_count(in, "scans", 0);
  p.first = read_count(in, "first", 0);
  p.min_points = read_count(in, "min_points", p.min_points);
  p.ellipse_every = read_count(in, "ellipse_every", p.ellipse_every);
  p.revisit_gap = read_count(in, "revisit_gap", p.revisit_gap);
  p.spike_window = read_count(in, "spike_window", p.spike_window);
  p.compare_scans = read_count(in, "compare_scans", 0);
  in.read("failures_are_results", p.failures_are_results);
  const YAML::Node slam = in.child("slam");
  if (slam && !slam.IsNull() && !slam.IsMap()) in.fail("slam", "key 'slam' must be a map");
  for (const char* key : {"filter", "filter_settings"}) {
    if (slam.IsMap() && slam[key].IsDefined())
      throw InputError(config.file, at_line(yaml_line(slam[key])),
                       std::string("key '") + key + "': set the filter per method, not under slam");
  }
  p.slam = read_plane_slam_settings(slam, config.file);  // errors name the line of the key
  std::vector<long> at;
  in.read("information_at", at);
  for (long a : at) {
    if (a < 0) in.fail("information_at", "key 'information_at': map sizes must be ≥ 0");
    p.information_at.push_back(static_cast<std::size_t>(a));
  }
  in.read("nees_probability", p.nees_probability);
  in.read("marginal_nees", p.marginal_nees);
  in.read("revisit_radius", p.revisit_radius);
  in.read("spike_threshold", p.spike_threshold);
  if (in.has("claims")) p.claims = in.child("claims");
  if (in.has("hybrid")) p.hybrid = read_hybrid_params(in.child("hybrid"), config.file);
  in.finish();
  std::string why;
  if (!p.valid(&why)) in.fail("", why);
  return p;
}

PlaneSlamMethod read_plane_slam_method(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  PlaneSlamMethod m;
  in.require("name", m.name);
  std::string filter;
  in.require("filter", filter);
  const YAML::Node filter_settings = in.child("filter_settings");
  m.scans = read_count(in, "scans", 0);
  m.motion =
      read_choice<MotionSource>(in, "motion", MotionSource::kOdometry,
                                {{"odometry", MotionSource::kOdometry}, {"fbmlndt", MotionSource::kFbmlndt}});
  if (in.has("matcher")) m.matcher = YAML::Clone(in.child("matcher"));
  if (in.has("landmarks"))
    m.landmarks = read_choice<LandmarkSource>(
        in, "landmarks", LandmarkSource::kTrue,
        {{"true", LandmarkSource::kTrue}, {"extracted", LandmarkSource::kExtracted}});
  if (in.has("odometry")) {
    YAML::Node campus(YAML::NodeType::Map);
    campus["odometry"] = YAML::Clone(in.child("odometry"));
    m.odometry = synth::read_campus_settings(campus, file).odometry;  // checks keys, types and bounds
  }
  in.finish();
  if (m.matcher && !m.matcher.IsNull() && m.motion != MotionSource::kFbmlndt)
    in.fail("matcher", "key 'matcher': only with motion: fbmlndt");
  if (m.motion == MotionSource::kFbmlndt) (void)read_mlndt_settings(m.matcher, file);
  if (!default_filter_spec(filter))
    in.fail("filter",
            "key 'filter': '" + filter + "' is not a filter (ekf, ukf, ckf, rspkf, seif, eif, eseif)");
  m.filter = read_filter_spec(filter, filter_settings, file, PlaneSlamModel().pose_dim());
  return m;
}

PlaneSlamSettings plane_slam_settings(const PlaneSlamParams& params, const PlaneSlamMethod& method,
                                      double p0_scale, const std::string& file) {
  PlaneSlamSettings s = params.slam;
  s.filter = method.filter.name();
  s.filter_factory = filter_factory(method.filter);
  if (std::isfinite(p0_scale)) s.p0_scale = p0_scale;
  std::string why;
  if (!s.valid(&why)) throw InputError(file, "", "plane SLAM settings: " + why);
  s.record_pose_covariance = false;  // the kind reads the pose block itself (joint_covariance)
  return s;
}

void check_plane_slam_sweep(const ExperimentConfig& config) {
  for (const auto& axis : config.sweep) {
    if (axis.name != kP0ScaleAxis)
      throw InputError(config.file, at_line(axis.values.empty() ? 0 : yaml_line(axis.values.front())),
                       "key '" + axis.name + "': the plane_slam kind sweeps only p0_scale");
    for (const YAML::Node& v : axis.values) {
      double x = 0.0;
      try {
        x = v.as<double>();
      } catch (const YAML::Exception&) {
        x = -1.0;
      }
      if (!(x > 0.0))
        throw InputError(config.file, at_line(yaml_line(v)),
                         "key 'p0_scale': '" + YAML::Dump(v) + "' is not a positive number");
    }
  }
}

}  // namespace sextant
