#include "sextant/eval/yaml.hpp"

#include <stdexcept>

#include "sextant/core/settings_reader.hpp"

namespace sextant {

namespace {

/// valid() messages start with the offending key ("delta must be > 0"): report at its line.
template <class Settings>
void check(const SettingsReader& in, const Settings& s) {
  std::string why;
  if (!s.valid(&why)) in.fail(why.substr(0, why.find(' ')), why);
}

}  // namespace

SuccessCriterion read_success_criterion(const YAML::Node& node, const std::string& file) {
  if (node.IsDefined() && node.IsScalar()) {
    try {
      return thesis_success_criterion(node.as<std::string>());
    } catch (const std::invalid_argument& e) {
      throw InputError(file, at_line(yaml_line(node)), e.what());
    }
  }
  SettingsReader in(node, file);
  SuccessCriterion s;
  in.read("max_translation_cm", s.max_translation_cm);
  in.read("max_rotation_deg", s.max_rotation_deg);
  in.read("require_converged", s.require_converged);
  in.finish();
  check(in, s);
  return s;
}

RegistrationStatsSettings read_registration_stats_settings(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  RegistrationStatsSettings s;
  std::string axes = "internal";
  if (in.read("axes", axes)) {
    if (axes == "uos")
      s.axes = AxisConvention::uos;
    else if (axes != "internal")
      in.fail("axes", "key 'axes': '" + axes + "' is not internal or uos");
  }
  if (in.has("success")) s.success = read_success_criterion(in.child("success"), file);
  in.read("errors_of_successes_only", s.errors_of_successes_only);
  in.finish();
  check(in, s);
  return s;
}

RpeSettings read_rpe_settings(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  RpeSettings s;
  std::string unit = "frames";
  if (in.read("unit", unit)) {
    if (unit == "meters")
      s.unit = RpeSettings::Unit::meters;
    else if (unit != "frames")
      in.fail("unit", "key 'unit': '" + unit + "' is not frames or meters");
  }
  in.read("delta", s.delta);
  in.read("all_pairs", s.all_pairs);
  in.read("tolerance", s.tolerance);
  in.finish();
  check(in, s);
  return s;
}

KittiDriftSettings read_kitti_drift_settings(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  KittiDriftSettings s;
  in.read("segment_lengths", s.segment_lengths);
  in.read("step", s.step);
  in.finish();
  check(in, s);
  return s;
}

}  // namespace sextant
