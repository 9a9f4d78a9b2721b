// Locating Debian's three.js (libjs-three) at run time, and copying it beside a folder of pages
// that share one copy (the report) instead of each inlining it.
#include <fstream>
#include <sstream>

#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "sextant/eval/cloud_view.hpp"

namespace sextant {
namespace {

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::filesystem::path find_three_js(const std::filesystem::path& dir) {
  const std::filesystem::path path = dir / "three.min.js";
  if (!std::filesystem::is_regular_file(path))
    throw InputError(path.string(), "",
                     "three.js not found: the 3D views need the Debian package libjs-three "
                     "(apt-get install libjs-three), which installs it there");
  return path;
}

std::filesystem::path write_three_js(const std::filesystem::path& folder, const std::filesystem::path& dir) {
  const std::string js = read_bytes(find_three_js(dir));
  const std::filesystem::path target = folder / "three.min.js";
  if (!std::filesystem::is_regular_file(target) || read_bytes(target) != js)
    write_file_atomically(target, js);
  return target;
}

}  // namespace sextant
