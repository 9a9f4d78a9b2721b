#pragma once
// The pose-graph and loop-closure settings from YAML (target Sextant::posegraph_yaml; the library
// takes the plain structs). InputError naming the file, the line and the key for every problem.
#include <string>

#include <yaml-cpp/yaml.h>

#include "sextant/posegraph/loop_closure.hpp"
#include "sextant/posegraph/pose_graph.hpp"

namespace sextant {

/// Reads PoseGraphSettings keys (loss: none|huber|cauchy, loss_scale, robust_odometry, max_iterations,
/// function_tolerance, threads) from a YAML map (may be null).
PoseGraphSettings read_pose_graph_settings(const YAML::Node& node, const std::string& file);

/// Reads LoopClosureSettings keys from a YAML map (may be null).
LoopClosureSettings read_loop_closure_settings(const YAML::Node& node, const std::string& file);

}  // namespace sextant
