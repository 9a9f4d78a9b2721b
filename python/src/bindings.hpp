#pragma once
// The module's topics, each adding its functions and classes to the module in its own file
// (module.cpp calls them in this order).
#include <pybind11/pybind11.h>

namespace sextant::python {

void bind_errors(pybind11::module_& m);    ///< module.cpp: InputError
void bind_clouds(pybind11::module_& m);    ///< clouds.cpp: read_cloud, write_cloud
void bind_poses(pybind11::module_& m);     ///< poses.cpp: pose_to_matrix, matrix_to_pose
void bind_match(pybind11::module_& m);     ///< match.cpp: match, MatchResult
void bind_odometry(pybind11::module_& m);  ///< odometry.cpp: odometry, OdometryRun
void bind_metrics(pybind11::module_& m);   ///< metrics.cpp: the submodule metrics

}  // namespace sextant::python
