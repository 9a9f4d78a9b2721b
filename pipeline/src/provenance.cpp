#include "sextant/pipeline/provenance.hpp"

#include <unistd.h>

#include <array>
#include <cstdio>
#include <ctime>

#include <ceres/version.h>
#include <oneapi/tbb/version.h>
#include <Eigen/Core>
#include <boost/version.hpp>

#include "sextant/pipeline/json.hpp"

#include "sextant_build_info.hpp"

namespace sextant {
namespace {

/// Output of a shell command (stdout, trailing newline removed); nullopt-like empty + ok=false on failure.
bool run_command(const std::string& command, std::string& output) {
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return false;
  std::array<char, 256> buf{};
  output.clear();
  while (std::fgets(buf.data(), static_cast<int>(buf.size()), pipe)) output += buf.data();
  const int status = ::pclose(pipe);
  while (!output.empty() && (output.back() == '\n' || output.back() == '\r')) output.pop_back();
  return status == 0;
}

}  // namespace

std::string sextant_version() {
  return SEXTANT_VERSION;
}

GitState current_git_state() {
  GitState state;
  const std::string git = "git -C '" + std::string(SEXTANT_SOURCE_DIR) + "' ";
  std::string sha, status;
  if (run_command(git + "rev-parse HEAD 2>/dev/null", sha) && sha.size() == 40 &&
      run_command(git + "status --porcelain --untracked-files=no 2>/dev/null", status)) {
    state.sha = sha;
    state.dirty = !status.empty();
    state.source = "git";
    return state;
  }
  state.sha = SEXTANT_GIT_SHA;
  state.dirty = SEXTANT_GIT_DIRTY != 0;
  state.source = "configure";
  return state;
}

std::string library_versions_json() {
  const std::string eigen = std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) +
                            "." + std::to_string(EIGEN_MINOR_VERSION);
  const std::string nlohmann = std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
                               std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." +
                               std::to_string(NLOHMANN_JSON_VERSION_PATCH);
  const std::string boost = std::to_string(BOOST_VERSION / 100000) + "." +
                            std::to_string(BOOST_VERSION / 100 % 1000) + "." +
                            std::to_string(BOOST_VERSION % 100);
  return json_line(Json{{"eigen", eigen},
                        {"yaml-cpp", SEXTANT_YAMLCPP_VERSION},
                        {"tbb", TBB_VERSION_STRING},
                        {"ceres", CERES_VERSION_STRING},
                        {"pcl", SEXTANT_PCL_VERSION},
                        {"fmt", SEXTANT_FMT_VERSION},
                        {"nlohmann-json", nlohmann},
                        {"boost", boost}});
}

std::string host_name() {
  std::array<char, 256> buf{};
  if (::gethostname(buf.data(), buf.size() - 1) != 0) return "unknown";
  return buf.data();
}

std::string iso_time_now() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  ::localtime_r(&now, &local);
  char buf[40];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S%z", &local);
  return buf;
}

}  // namespace sextant
