#pragma once
// The metric settings from YAML, for experiment configs (target Sextant::eval_yaml; the library
// takes the plain structs). Every problem (unknown key, wrong
// type, bad value) is an InputError naming the file, line and key.
//
//   success: translation_50cm                 # a preset name, or a map:
//   success: {max_translation_cm: 200, max_rotation_deg: 10, require_converged: false}
//   errors:  {axes: uos, success: translation_50cm, errors_of_successes_only: true}
//   rpe:     {unit: meters, delta: 10, all_pairs: false, tolerance: 0.1}
//   kitti:   {segment_lengths: [100, 200, 400], step: 10}
#include <string>

#include <yaml-cpp/yaml.h>

#include "sextant/eval/registration_metrics.hpp"
#include "sextant/eval/trajectory_metrics.hpp"

namespace sextant {

/// A preset name (see thesis_success_criterion) or a map; null keeps the defaults.
SuccessCriterion read_success_criterion(const YAML::Node& node, const std::string& file);
/// Keys: axes (internal | uos), success, errors_of_successes_only.
RegistrationStatsSettings read_registration_stats_settings(const YAML::Node& node, const std::string& file);
/// Keys: unit (frames | meters), delta, all_pairs, tolerance.
RpeSettings read_rpe_settings(const YAML::Node& node, const std::string& file);
/// Keys: segment_lengths, step.
KittiDriftSettings read_kitti_drift_settings(const YAML::Node& node, const std::string& file);

}  // namespace sextant
