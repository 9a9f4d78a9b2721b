#pragma once
// The dataset a user names, as both faces open it (`sextant odometry <dataset>`, `sextant match --index`,
// sextant.odometry("…")): the built-in synthetic campus by name, a recording (a ROS 1 bag, an MCAP file, a
// ROS 2 bag folder: recordings/recording.hpp) with the part of it chosen, else a folder (core's
// open_dataset: a folder of scans, a uos folder or a KITTI sequence), with a ground-truth file for a plain
// folder of scans.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "sextant/core/dataset.hpp"
#include "sextant/pipeline/odometry_request.hpp"
#include "sextant/recordings/recording.hpp"

namespace sextant {

/// "campus" or "synthetic": the built-in synthetic campus.
bool names_builtin_campus(const std::string& name);

/// The built-in synthetic campus with the default settings, generated from `seed`.
std::unique_ptr<Dataset> open_builtin_campus(std::uint64_t seed);

/// The dataset `name` names; `poses`: a TUM or KITTI ground-truth file for a plain folder of scans (the
/// face's `poses` argument); `selection`: the topic and part of a recording (the face's `topic`, `start`,
/// `duration` and `every` arguments). InputError naming `name` for a missing folder or a file that is no
/// recording, naming the poses argument for poses given with the campus, a recording or a folder that
/// brings its own, naming the selection's argument for a bad value or a selection of something that is not
/// a recording; the readers' InputErrors name their files.
std::unique_ptr<Dataset> open_dataset_argument(const std::string& name,
                                               const std::optional<std::string>& poses,
                                               std::uint64_t campus_seed, Face face,
                                               RecordingSelection selection = {});

/// InputError naming the face's argument (--start, duration=, …) when `selection` is not valid.
void check_recording_selection(const RecordingSelection& selection, Face face);

}  // namespace sextant
