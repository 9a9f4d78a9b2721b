#pragma once
// The dataset a user names, as both faces open it (`sextant odometry <dataset>`, `sextant info`,
// sextant.odometry("…")): the built-in synthetic campus by name, else a folder (core's open_dataset: a
// folder of scans, a uos folder or a KITTI sequence), with a ground-truth file for a plain folder of scans.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "sextant/core/dataset.hpp"
#include "sextant/pipeline/odometry_request.hpp"

namespace sextant {

/// "campus" or "synthetic": the built-in synthetic campus.
bool names_builtin_campus(const std::string& name);

/// The built-in synthetic campus with the default settings, generated from `seed`.
std::unique_ptr<Dataset> open_builtin_campus(std::uint64_t seed);

/// The dataset `name` names; `poses`: a TUM or KITTI ground-truth file for a plain folder of scans (the
/// face's `poses` argument). InputError naming `name` for a missing folder or a file, naming the poses
/// argument for poses given with the campus or a folder that brings its own; the readers' InputErrors
/// name their files.
std::unique_ptr<Dataset> open_dataset_argument(const std::string& name,
                                               const std::optional<std::string>& poses,
                                               std::uint64_t campus_seed, Face face);

}  // namespace sextant
