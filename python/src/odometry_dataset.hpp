#pragma once
// The dataset argument of sextant.odometry(): a folder or a recording (pipeline's open_dataset_argument, as
// `sextant odometry`, with a ground-truth file for a folder of scans and the part of a recording chosen),
// "campus" (the built-in synthetic campus, as the CLI), or a list of clouds held in memory
// (MemoryDataset) with optional ground truth, odometry and times.
#include <cstdint>
#include <memory>

#include <pybind11/pybind11.h>

#include "sextant/core/dataset.hpp"
#include "sextant/recordings/recording.hpp"

namespace sextant::python {

/// InputError for a missing folder or bad files (the library's), ValueError/TypeError for bad
/// arguments (pose or time counts, one array instead of a list, list-only arguments with a folder, a
/// recording's selection with a list).
std::unique_ptr<Dataset> open_odometry_dataset(const pybind11::object& source, const pybind11::object& poses,
                                               const pybind11::object& odometry_poses,
                                               const pybind11::object& times, std::uint64_t campus_seed,
                                               const RecordingSelection& selection = {});

}  // namespace sextant::python
