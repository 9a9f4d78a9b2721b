// The FbML-NDT and PCL-peer settings from YAML (Sextant::matchers_yaml).
#include "readers.hpp"

#include "sextant/features/yaml.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant {

namespace {

ConstraintThresholds read_constraint_thresholds(const YAML::Node& node, const std::string& file) {
  ConstraintThresholds t;
  SettingsReader in(node, file);
  in.read("min_planes", t.min_planes);
  in.read("min_inliers", t.min_inliers);
  in.read("min_normal_spread", t.min_normal_spread);
  in.read("min_information_ratio", t.min_information_ratio);
  in.finish();
  std::string why;
  if (!t.valid(&why)) in.fail("", why);
  return t;
}

FbsFallback read_fallback(SettingsReader& in) {
  std::string name = "gbs";
  in.read("fallback", name);
  if (name == "add_gbs") return FbsFallback::kAddGbs;
  if (name == "gbs") return FbsFallback::kGbs;
  if (name == "none") return FbsFallback::kNone;
  in.fail("fallback", "key 'fallback': '" + name + "' is not gbs, add_gbs or none");
  return FbsFallback::kNone;
}

}  // namespace

FbmlndtSettings read_fbmlndt_settings(const YAML::Node& node, const std::string& file) {
  FbmlndtSettings s;
  YAML::Node rest;
  bool verify_given = false;
  {
    // The nested settings are read even when absent (their defaults), so that a SettingsRecording
    // holds them all.
    SettingsReader in(node && node.IsMap() ? node : YAML::Node(), file);
    in.read("seed", s.seed);
    s.features = read_plane_extraction_settings(in.child("features"), file);
    s.fallback = read_fallback(in);
    s.constraints = read_constraint_thresholds(in.child("constraints"), file);
    s.fallback_gbs = read_grid_sampler_settings(in.child("fallback_gbs"), file);
    verify_given = in.has("verify");
    if (node && node.IsMap()) {
      rest = YAML::Clone(node);  // the remaining keys belong to mlndt (which rejects unknown ones)
      for (const char* own : {"seed", "features", "fallback", "constraints", "fallback_gbs", "verify"})
        rest.remove(own);
    }
    s.mlndt = read_mlndt_settings(rest, file);
    if (!verify_given) s.verify = s.mlndt.refine_first;
    in.read("verify", s.verify);  // after mlndt: its default follows refine_first
  }
  return s;
}

namespace {

template <class Settings>
void check(const Settings& s, const SettingsReader& in) {
  in.finish();
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
}

}  // namespace

PclNdtSettings read_pcl_ndt_settings(const YAML::Node& node, const std::string& file) {
  PclNdtSettings s;
  SettingsReader in(node, file);
  in.read("resolution", s.resolution);
  in.read("step_size", s.step_size);
  in.read("epsilon", s.epsilon);
  in.read("max_iterations", s.max_iterations);
  in.read("outlier_ratio", s.outlier_ratio);
  check(s, in);
  return s;
}

PclIcpSettings read_pcl_icp_settings(const YAML::Node& node, const std::string& file) {
  PclIcpSettings s;
  SettingsReader in(node, file);
  in.read("max_correspondence_distance", s.max_correspondence_distance);
  in.read("max_iterations", s.max_iterations);
  in.read("epsilon", s.epsilon);
  in.read("fitness_epsilon", s.fitness_epsilon);
  check(s, in);
  return s;
}

PclGicpSettings read_pcl_gicp_settings(const YAML::Node& node, const std::string& file) {
  PclGicpSettings s;
  SettingsReader in(node, file);
  in.read("max_correspondence_distance", s.max_correspondence_distance);
  in.read("max_iterations", s.max_iterations);
  in.read("epsilon", s.epsilon);
  in.read("correspondence_randomness", s.correspondence_randomness);
  in.read("max_optimizer_iterations", s.max_optimizer_iterations);
  check(s, in);
  return s;
}

}  // namespace sextant
