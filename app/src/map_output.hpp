#pragma once
// `sextant odometry --map-out PATH`: where the run's map (run_map.hpp) is written. The path is checked
// before the run (an extension other than .ply or .pcd is a usage error then, not after an hour's
// run). A path inside --out is written into the run's staging folder with the run's other files, so
// that the output folder stays all or nothing (output_folder.hpp); a path outside it is written
// atomically (core/atomic_file.hpp) just before the output folder is committed, so that a map that
// cannot be written fails the run and leaves the earlier output folder as it was.
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

#include "sextant/core/output_folder.hpp"
#include "sextant/core/point_cloud.hpp"

namespace sextant::cli {

/// Empty when `path` ends in .ply or .pcd (any case), else what is wrong.
std::string map_file_problem(const std::filesystem::path& path);
/// --map-out's check (map_file_problem): a usage error, exit 2, before anything runs.
CLI::Validator map_file();

/// --map-out, --map-voxel and --map-trusted-only of `sextant odometry`, into the three settings.
void add_map_options(CLI::App& cmd, std::string& map_out_path, double& map_voxel, bool& map_trusted_only);

class MapOutput {
 public:
  /// InputError("--map-out", …) for an extension other than .ply / .pcd (map_file_problem), an existing
  /// folder, the output folder itself, or a path the output folder lies in.
  MapOutput(const std::filesystem::path& path, const std::filesystem::path& out_folder);

  /// The path as the user named it (what is printed).
  const std::filesystem::path& path() const { return path_; }
  /// Whether it lies inside --out (and so goes in with the run's files).
  bool inside_output_folder() const { return !inside_.empty(); }

  /// Writes `map` (binary PLY or PCD, by the extension; core/io/cloud_io.hpp), creating the folders it
  /// needs: into `folder`'s staging folder when the path lies inside --out, else at the path.
  void write(const OutputFolder& folder, const PointCloud& map) const;

 private:
  std::filesystem::path path_;
  std::filesystem::path inside_;  ///< the path relative to --out; empty when outside it
};

}  // namespace sextant::cli
