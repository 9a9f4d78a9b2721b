#pragma once
// Where a result came from: the resolved config, the code (git SHA + dirty flag), the libraries,
// the machine, the thread count and the times.
#include <string>

namespace sextant {

struct GitState {
  std::string sha;     ///< "unknown" when neither git nor the configure-time value is available
  bool dirty = false;  ///< uncommitted changes in the work tree
  std::string source;  ///< "git" (asked at run time) or "configure" (baked in at configure time)
};

/// The project version, "0.1.0".
std::string sextant_version();
/// Asks `git` in the source tree at run time; falls back to the SHA baked in at configure time.
GitState current_git_state();
/// {"eigen": "3.4.0", "yaml-cpp": ..., "tbb": ..., "ceres": ..., "pcl": ..., "fmt": ..., "nlohmann-json":
/// ..., "boost": ...} as one line of JSON.
std::string library_versions_json();
std::string host_name();
/// Local time as ISO 8601 ("2024-05-01T12:34:56+0200").
std::string iso_time_now();

}  // namespace sextant
