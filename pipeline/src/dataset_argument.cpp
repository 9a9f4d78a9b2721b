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

std::unique_ptr<Dataset> open_dataset_argument(const std::string& name,
                                               const std::optional<std::string>& poses,
                                               std::uint64_t campus_seed, Face face) {
  namespace fs = std::filesystem;
  if (names_builtin_campus(name)) {
    if (poses) throw InputError(argument(face, "poses"), "", "the campus brings its own ground truth");
    return open_builtin_campus(campus_seed);
  }
  const fs::path folder(name);
  if (!fs::exists(folder))
    throw FileError(name,
                    "no such dataset folder (expected a folder of scans, a uos folder, a KITTI sequence "
                    "folder, or 'campus')",
                    ENOENT);
  if (!fs::is_directory(folder))
    throw FileError(
        name, "is a file, expected a dataset folder (a folder of scans, uos or KITTI) or 'campus'", ENOTDIR);
  std::unique_ptr<Dataset> dataset = open_dataset(folder);
  if (!poses) return dataset;
  if (dataset->metadata().format != "folder")
    throw InputError(argument(face, "poses"), "",
                     "only for a plain folder of scans: this " + dataset->metadata().format +
                         " folder brings its own poses");
  return open_scan_folder(folder, *poses);
}

}  // namespace sextant
