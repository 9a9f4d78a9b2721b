#pragma once
// What `sextant odometry` records and prints of a run beyond the library's files (pipeline/
// odometry_output.hpp): its options, provenance.json, the sensor line and the per-step lines of -v.
#include <cstddef>
#include <cstdint>
#include <string>

#include <yaml-cpp/yaml.h>

#include "matcher_options.hpp"
#include "sextant/core/dataset.hpp"
#include "sextant/odometry/odometry.hpp"

namespace sextant::cli {

struct OdometryOptions : MatcherOptions {
  std::string dataset, out;
  std::string poses;  ///< ground truth for a scan folder: TUM or KITTI file (default: poses.txt beside it)
  std::string guess;  ///< empty: odometry when the dataset has it, else constant_velocity
  std::string map = "local_map";
  std::string loop_closure;       ///< empty: none; proximity, descriptor or both
  std::string sensor = "auto";    ///< auto, spinning, solid_state
  std::string platform = "auto";  ///< auto, car, handheld
  std::size_t first = 0;
  std::size_t scans = 0;  ///< 0: to the end of the dataset
  std::size_t local_map_scans = 5;
  double min_range = 0.0;
  double max_acceleration = OdometrySettings{}.max_acceleration;
  std::uint64_t seed = 1;
  std::uint64_t campus_seed = 1;
  int jobs = 0;
  bool no_progress = false;
  bool no_recover = false;
  bool no_deskew = false;
  bool common_view = false;  ///< --common-view: whatever the method
  bool whole_scans = false;  ///< --whole-scans: whatever the method
  bool print_config = false;
};

/// provenance.json: the command, the dataset, the settings as given and as resolved, the sensor and
/// platform the checks assumed, the git state, the libraries' versions, the host and the times.
std::string provenance_json(const OdometryOptions& o, const MatcherConfig& config,
                            const DatasetMetadata& meta, const OdometrySettings& s,
                            const OdometryResult& result, std::size_t scans, const std::string& start,
                            double seconds);

/// -v: one line per registration (steps.csv has every column).
void print_steps(const OdometryResult& result, std::size_t first);

/// The sensor and platform the checks assumed, and why (printed after the run, recorded in provenance).
std::string sensor_line(const OdometrySettings& s, const OdometryResult& r);

}  // namespace sextant::cli
