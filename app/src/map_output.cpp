#include "map_output.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <system_error>

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

}  // namespace sextant::cli
