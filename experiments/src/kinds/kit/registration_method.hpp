#pragma once
// A registration method of an experiment config, as the registration and sequence kinds read it:
//
//   methods:
//     - {name: mlndt, matcher: mlndt, settings: {solver: lm}, sampler: gbs, sampler_settings: {...},
//        adaptive_start: {...}}   # optional: the thesis' adaptive starting layer (adaptive_start.hpp)
#include <string>

#include <yaml-cpp/yaml.h>

#include "kit/adaptive_start.hpp"
#include "sextant/matchers/matcher_spec.hpp"

namespace sextant {

struct RegistrationMethod {
  std::string name;
  MatcherSpec matcher;
  SamplerSpec sampler = AllPointsSettings{};
  bool adaptive = false;  ///< `adaptive_start` given: the thesis' adaptive starting layer
  AdaptiveStartSettings adaptive_start;
};

/// Does a method's node ask for the adaptive starting layer? Without reading (or checking) the rest:
/// cheap enough for RunKind::planned_runs. read_registration_method sets `adaptive` exactly then.
inline bool declares_adaptive_start(const YAML::Node& node) {
  return node.IsMap() && node["adaptive_start"].IsDefined();
}

/// Reads and checks one method (the matcher's and sampler's names and settings).
RegistrationMethod read_registration_method(const YAML::Node& node, const std::string& file);

}  // namespace sextant
