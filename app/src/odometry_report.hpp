#pragma once
// What `sextant odometry` records and prints of a run beyond the library's files (pipeline/
// odometry_output.hpp): its options, provenance.json, the sensor line and the per-step lines of -v.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include <yaml-cpp/yaml.h>

#include "matcher_options.hpp"
#include "sextant/core/dataset.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/pipeline/run_map_builder.hpp"
#include "sextant/recordings/recording.hpp"

namespace sextant::cli {

struct OdometryOptions : MatcherOptions {
  /// The part of a recording the options choose (--topic, --start, --duration, --every).
  RecordingSelection recording_selection() const;

  std::string dataset, out;
  std::string poses;  ///< ground truth for a scan folder: TUM or KITTI file (default: poses.txt beside it)
  std::string guess;  ///< empty: odometry when the dataset has it, else constant_velocity
  std::string map = "local_map";
  std::string loop_closure;       ///< empty: none; proximity, descriptor or both
  std::string view;               ///< empty: none; else the run's HTML view (run_view.hpp)
  std::string sensor = "auto";    ///< auto, spinning, solid_state
  std::string platform = "auto";  ///< auto, car, handheld
  std::string topic;              ///< a recording's PointCloud2 topic (empty: its only one)
  double start = 0.0;             ///< [s] from the recording's start
  double duration = std::numeric_limits<double>::quiet_NaN();  ///< [s]; NaN: to the end
  std::size_t every = 1;                                       ///< every N-th message of the topic
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
  std::string map_out;            ///< --map-out: empty, or a .ply / .pcd file
  double map_voxel = 0.0;         ///< --map-voxel [m]; 0: the default (RunMapSettings)
  bool map_trusted_only = false;  ///< --map-trusted-only
};

/// provenance.json: the command, the dataset, the settings as given and as resolved, the sensor and
/// platform the checks assumed, the git state, the libraries' versions, the host and the times.
/// `map`: the run's map when --map-out asked for one.
std::string provenance_json(const OdometryOptions& o, const MatcherConfig& config,
                            const DatasetMetadata& meta, const OdometrySettings& s,
                            const OdometryResult& result, std::size_t scans, const std::string& start,
                            double seconds, const std::optional<RunMapSummary>& map);

/// -v: one line per registration (steps.csv has every column).
void print_steps(const OdometryResult& result, std::size_t first);

/// The sensor and platform the checks assumed, and why (printed after the run, recorded in provenance).
std::string sensor_line(const OdometrySettings& s, const OdometryResult& r);

}  // namespace sextant::cli
