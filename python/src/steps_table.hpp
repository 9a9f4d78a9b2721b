#pragma once
// The per-step table of sextant.odometry(): the columns of `sextant odometry`'s steps.csv
// (pipeline/steps_table.hpp), in its order, each a NumPy array (int64, float64,
// bool or str); error_m and error_deg are NaN without ground truth (empty in the CSV) and free text
// keeps its commas (the CSV turns them into ';').
#include <cstddef>
#include <optional>
#include <vector>

#include <pybind11/pybind11.h>
#include <Eigen/Geometry>

#include "sextant/odometry/odometry.hpp"

namespace sextant::python {

pybind11::dict steps_columns(const OdometryResult& result, std::size_t first,
                             const std::optional<std::vector<Eigen::Isometry3d>>& truth);

}  // namespace sextant::python
