#include "map_output.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <system_error>

#include "number_options.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/cloud_io.hpp"

namespace sextant::cli {
namespace {

namespace fs = std::filesystem;

/// `path` absolute, with its existing part's symbolic links resolved, so that two spellings of one
/// place compare equal.
fs::path resolved(const fs::path& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path), ec);
  if (ec) p = fs::absolute(path).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();  // "out/" names the folder "out"
  return p;
}

/// `inner` relative to `outer` when it lies inside it (or is it: "."), else empty.
fs::path inside(const fs::path& inner, const fs::path& outer) {
  const fs::path relative = inner.lexically_relative(outer);
  if (relative.empty() || *relative.begin() == "..") return {};
  return relative;
}

}  // namespace

std::string map_file_problem(const fs::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".ply" || extension == ".pcd") return {};
  return "expected a .ply or .pcd file (the map is written as binary PLY or PCD), got '" + path.string() +
         "'";
}

CLI::Validator map_file() {
  return CLI::Validator([](std::string& text) { return map_file_problem(text); }, "FILE.ply|FILE.pcd");
}

MapOutput::MapOutput(const fs::path& path, const fs::path& out_folder) : path_(path) {
  if (const std::string problem = map_file_problem(path); !problem.empty())
    throw InputError("--map-out", "", problem);
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw InputError("--map-out", "", "'" + path.string() + "' is a folder: name the map's file");
  const fs::path map = resolved(path), out = resolved(out_folder);
  inside_ = inside(map, out);
  if (inside_ == ".")
    throw InputError("--map-out", "", "'" + path.string() + "' is the output folder (--out): name a file");
  if (!inside(out, map).empty())
    throw InputError(
        "--map-out", "",
        "the output folder (--out " + out_folder.string() + ") lies inside '" + path.string() + "'");
}

void MapOutput::write(const OutputFolder& folder, const PointCloud& map) const {
  const fs::path file = inside_output_folder() ? folder.staging() / inside_ : path_;
  if (const fs::path parent = file.parent_path(); !parent.empty()) {
    std::error_code ec;
    fs::create_directories(parent, ec);
    if (ec) throw FileError::from_errno(parent.string(), "cannot create the map's folder", ec.value());
  }
  write_cloud(file, map);
}

void add_map_options(CLI::App& cmd, std::string& map_out_path, double& map_voxel, bool& map_trusted_only) {
  CLI::Option* map_out =
      cmd.add_option(
             "--map-out", map_out_path,
             "Write the run's map: every scan (as registered: its sensor's frame, without "
             "--min-range's points) moved into the world by its pose and voxel-filtered, one point "
             "per occupied voxel at the centroid of its points, with their mean intensity when every "
             "scan has one; binary .ply or .pcd by the extension, written atomically; inside --out it "
             "goes in with the run's files. Built as the run goes (memory grows with the occupied "
             "voxels, not with the scans); with --loop-closure after the loops are closed, from the "
             "closed poses. Scans placed by untrusted steps go in too (the map shows where the run "
             "went wrong) unless --map-trusted-only")
          ->check(map_file());
  cmd.add_option("--map-voxel", map_voxel,
                 "The map's voxel edge [m] (default: 1/100 of the first scan's median range, rounded to 1, 2 "
                 "or 5 × 10ⁿ, at least 0.01; printed and recorded in provenance.json)")
      ->check(finite_number(0.0, /*strictly=*/true))
      ->needs(map_out);
  cmd.add_flag("--map-trusted-only", map_trusted_only,
               "Leave the scans placed by untrusted steps out of the map (counted and printed); the scans "
               "after them stay, placed by the chain")
      ->needs(map_out);
}

}  // namespace sextant::cli
