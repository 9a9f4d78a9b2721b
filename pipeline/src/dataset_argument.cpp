// The dataset a user names (dataset_argument.hpp).
#include "sextant/pipeline/dataset_argument.hpp"

#include <cerrno>
#include <filesystem>

#include "sextant/core/error.hpp"
#include "sextant/synth/campus.hpp"

namespace sextant {

bool names_builtin_campus(const std::string& name) {
  return name == "campus" || name == "synthetic";
}

std::unique_ptr<Dataset> open_builtin_campus(std::uint64_t seed) {
  return std::make_unique<synth::CampusDataset>(synth::generate_campus(synth::CampusSettings{}, seed));
}

void check_recording_selection(const RecordingSelection& s, Face face) {
  const auto [field, problem] = s.problem();
  if (!field.empty()) throw InputError(argument(face, field), "", problem);
}

std::unique_ptr<Dataset> open_dataset_argument(const std::string& name,
                                               const std::optional<std::string>& poses,
                                               std::uint64_t campus_seed, Face face,
                                               RecordingSelection selection) {
  namespace fs = std::filesystem;
  check_recording_selection(selection, face);
  selection.topic_argument = face == Face::python ? "topic=" : "--topic";
  const std::string chosen = !selection.topic.empty() ? "topic"
                             : selection.start != 0.0 ? "start"
                             : selection.duration     ? "duration"
                             : selection.every != 1   ? "every"
                                                      : "";
  if (names_builtin_campus(name)) {
    if (poses) throw InputError(argument(face, "poses"), "", "the campus brings its own ground truth");
    if (!chosen.empty()) throw InputError(argument(face, chosen), "", "only for a recording, not the campus");
    return open_builtin_campus(campus_seed);
  }
  const fs::path folder(name);
  if (!fs::exists(folder))
    throw FileError(name,
                    "no such dataset folder or recording (expected a folder of scans, a uos folder, a KITTI "
                    "sequence folder, a ROS 1 .bag, an .mcap file, a ROS 2 bag folder, or 'campus')",
                    ENOENT);
  if (is_recording(folder)) {
    if (poses)
      throw InputError(argument(face, "poses"), "", "only for a plain folder of scans, not a recording");
    return open_recording(folder, selection);
  }
  if (!chosen.empty())
    throw InputError(
        argument(face, chosen), "",
        "only for a recording (a ROS 1 .bag, an .mcap file, a ROS 2 bag folder): " + name + " is not one");
  if (!fs::is_directory(folder))
    throw FileError(
        name,
        "is a file, expected a dataset folder (a folder of scans, uos or KITTI), a recording (.bag, "
        ".mcap, a ROS 2 bag folder) or 'campus'",
        ENOTDIR);
  std::unique_ptr<Dataset> dataset = open_dataset(folder);
  if (!poses) return dataset;
  if (dataset->metadata().format != "folder")
    throw InputError(argument(face, "poses"), "",
                     "only for a plain folder of scans: this " + dataset->metadata().format +
                         " folder brings its own poses");
  return open_scan_folder(folder, *poses);
}

}  // namespace sextant
