#include "registration/settings.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "registration/layouts/layouts.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/matchers/feature_based_sampler.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/sampler.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant {
namespace {

[[noreturn]] void axis_fail(const ExperimentConfig& config, const YAML::Node& where,
                            const std::string& problem) {
  throw InputError(config.file, at_line(yaml_line(where)), problem);
}

double axis_number(const ExperimentConfig& config, const SweepAxis& axis, const YAML::Node& v) {
  try {
    if (v.IsScalar()) return v.as<double>();
  } catch (const YAML::Exception&) {
  }
  axis_fail(config, v, "key '" + axis.name + "': '" + YAML::Dump(v) + "' is not a number");
}

}  // namespace

bool RegistrationParams::valid(std::string* why) const {
  const auto fail = [why](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (pairs == PairSource::kDisplaced && guess != GuessSource::kIdentity)
    return fail("key 'guess': displaced pairs start from the identity (guess: identity)");
  if (pairs == PairSource::kDisplaced && scan == second) return fail("key 'second': must differ from 'scan'");
  return true;
}

RegistrationParams read_registration_params(const ExperimentConfig& config) {
  SettingsReader in(config.params, config.file);
  RegistrationParams p;
  std::string pairs = "consecutive", guess, axes = "uos", report = "accuracy";
  in.read("pairs", pairs);
  if (pairs == "consecutive") {
    p.pairs = PairSource::kConsecutive;
  } else if (pairs == "displaced") {
    p.pairs = PairSource::kDisplaced;
    p.guess = GuessSource::kIdentity;
  } else {
    in.fail("pairs", "key 'pairs': '" + pairs + "' is not consecutive or displaced");
  }
  if (in.read("guess", guess)) {
    if (guess == "odometry") {
      p.guess = GuessSource::kOdometry;
    } else if (guess == "identity") {
      p.guess = GuessSource::kIdentity;
    } else if (guess == "scaled") {
      p.guess = GuessSource::kScaled;
    } else {
      in.fail("guess", "key 'guess': '" + guess + "' is not odometry, identity or scaled");
    }
  }
  long scan = 0, second = -1;
  in.read("scan", scan);
  in.read("second", second);
  if (scan < 0) in.fail("scan", "key 'scan' must be ≥ 0");
  if (second < 0) second = scan + 1;
  p.scan = static_cast<std::size_t>(scan);
  p.second = static_cast<std::size_t>(second);
  in.read("success", p.success);
  try {
    (void)thesis_success_criterion(p.success);
  } catch (const std::exception&) {
    in.fail("success",
            "key 'success': '" + p.success + "' is not translation_50cm or translation_200cm_rotation_10deg");
  }
  in.read("axes", axes);
  if (axes == "uos") {
    p.axes = AxisConvention::uos;
  } else if (axes == "internal") {
    p.axes = AxisConvention::internal;
  } else {
    in.fail("axes", "key 'axes': '" + axes + "' is not uos or internal");
  }
  in.read("report", report);
  p.report = find_registration_layout(report);
  if (!p.report) in.fail("report", "key 'report': '" + report + "' is not " + registration_layout_names());
  in.read("baseline", p.baseline);
  in.read("proposed", p.proposed);
  p.displaced = in.child("displaced");
  in.read("thesis_baseline", p.thesis_baseline);
  in.read("thesis_proposed", p.thesis_proposed);
  in.finish();
  if (p.displaced.IsDefined() && !p.displaced.IsNull() && p.pairs != PairSource::kDisplaced)
    in.fail("displaced", "key 'displaced' is only used with pairs: displaced");
  std::string why;
  if (!p.valid(&why)) in.fail(why.find("'second'") != std::string::npos ? "second" : "guess", why);
  const std::pair<const char*, const std::string*> named[] = {{"baseline", &p.baseline},
                                                              {"proposed", &p.proposed},
                                                              {"thesis_baseline", &p.thesis_baseline},
                                                              {"thesis_proposed", &p.thesis_proposed}};
  for (const auto& [key, name] : named) {
    if (name->empty()) continue;
    const std::string& wanted = *name;  // C++17 lambdas cannot capture a structured binding
    const bool known = std::any_of(config.methods.begin(), config.methods.end(),
                                   [&](const MethodConfig& m) { return m.name == wanted; });
    if (!known) in.fail(key, "key '" + std::string(key) + "': no method named '" + *name + "'");
  }
  return p;
}

void check_registration_sweep(const ExperimentConfig& config, const RegistrationParams& params,
                              const std::vector<RegistrationMethod>& methods) {
  const auto& known = registration_axes();
  for (const auto& axis : config.sweep) {
    if (std::find(known.begin(), known.end(), axis.name) == known.end())
      axis_fail(config, axis.values.front(),
                "sweep axis '" + axis.name +
                    "' is not one of pair, tx, yaw, f, start_layer, scene, offset, direction");
    if (axis.name == "scene") continue;  // scene names (registration/scenes.cpp)
    for (const auto& v : axis.values) {
      const double x = axis_number(config, axis, v);
      if ((axis.name == "pair" || axis.name == "start_layer") && (x < 0 || x != std::floor(x)))
        axis_fail(config, v, "key '" + axis.name + "': '" + YAML::Dump(v) + "' must be an integer ≥ 0");
      if (axis.name == "f" && !(x >= 0 && x <= 1))
        axis_fail(config, v, "key 'f': " + YAML::Dump(v) + " is not in [0, 1]");
    }
  }
  const bool consecutive = params.pairs == PairSource::kConsecutive;
  if (consecutive && !find_axis(config, "pair"))
    throw InputError(config.file, "",
                     "key 'sweep': pairs: consecutive needs an axis 'pair' (reference scan indices)");
  if (!consecutive && find_axis(config, "pair"))
    axis_fail(config, find_axis(config, "pair")->values.front(),
              "sweep axis 'pair' is only used with pairs: consecutive");
  for (const char* name : {"tx", "yaw", "scene", "offset", "direction"}) {
    if (consecutive && find_axis(config, name))
      axis_fail(config, find_axis(config, name)->values.front(),
                "sweep axis '" + std::string(name) + "' is only used with pairs: displaced");
  }
  for (std::size_t k = 0; k < methods.size(); ++k) {
    if (!consecutive && methods[k].adaptive)
      throw InputError(config.file, at_line(yaml_line(config.methods[k].node)),
                       "key 'adaptive_start': the adaptive starting layer needs pairs: consecutive");
  }
  const bool scaled = params.guess == GuessSource::kScaled;
  if (scaled != (find_axis(config, "f") != nullptr))
    throw InputError(config.file, "", "key 'sweep': an axis 'f' is used exactly when params.guess is scaled");
  if (const SweepAxis* layers = find_axis(config, "start_layer")) {
    // Every method must accept the override (e.g. mlndt's start_layer in [1, layers]).
    for (const RegistrationMethod& method : methods) {
      for (const auto& v : layers->values) {
        MatcherSpec spec = method.matcher;
        std::string why = "it has no layer pyramid";
        if (!set_start_layer(spec, v.as<int>()) || !spec.valid(&why))
          axis_fail(
              config, v,
              "sweep axis 'start_layer': method '" + method.name + "' rejects " + YAML::Dump(v) + ": " + why);
      }
    }
  }
}

double point_value(const RunSpec& run, const std::string& axis, double fallback) {
  const auto it = run.point.find(axis);
  return it == run.point.end() ? fallback : std::stod(it->second);
}

std::vector<std::size_t> needed_scans(const ExperimentConfig& config, const RegistrationParams& params) {
  std::set<std::size_t> scans;
  if (params.pairs == PairSource::kDisplaced) {
    // The displaced scenes load their own scans (registration/scenes.hpp).
  } else {
    for (const auto& axis : config.sweep) {
      if (axis.name != "pair") continue;
      for (const auto& v : axis.values) {
        const auto i = v.as<std::size_t>();
        scans.insert(i);
        scans.insert(i + 1);
      }
    }
  }
  return {scans.begin(), scans.end()};
}

}  // namespace sextant
