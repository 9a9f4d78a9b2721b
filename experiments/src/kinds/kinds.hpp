#pragma once
// The built-in run kinds, one file each; registered in run_kind_registry.cpp.
#include <memory>

#include "sextant/experiments/run_kind.hpp"

namespace sextant {

std::unique_ptr<RunKind> make_metric_examples_kind();
std::unique_ptr<RunKind> make_plane_slam_kind();
std::unique_ptr<RunKind> make_place_recognition_kind();
std::unique_ptr<RunKind> make_pose_graph_kind();
std::unique_ptr<RunKind> make_registration_kind();
std::unique_ptr<RunKind> make_selftest_kind();
std::unique_ptr<RunKind> make_sequence_kind();
std::unique_ptr<RunKind> make_simulation_kind();
std::unique_ptr<RunKind> make_plane_features_kind();

}  // namespace sextant
