#pragma once
// One experiment, as written in experiments/eNN_<slug>.yaml:
//
//   name: e02_accuracy_100_scans      # result folder name
//   kind: registration                # which run kind executes it (run_kind.hpp)
//   title: "..."                       # shown in the report
//   thesis: "§5.1.1.2 A, tables 5.1-5.4"
//   seed: 1                           # base seed of every random choice
//   repetitions: 1                    # runs per (method, sweep point)
//   dataset: {source: synthetic, campus: {...}}   # or {source: folder, path: ...} or none; a folder's
//                                                 # path may be a recording (with topic, start, duration,
//                                                 every)
//   methods: [{name: ndt, ...}, ...]  # each method's settings, passed through to the kind
//   sweep: {axis: [values], pair: {from: 0, to: 99}}  # cartesian product of the axes
//   metrics: [...]                    # which metrics the report shows (the kind checks names)
//   params: {...}                     # kind-specific settings
//   reference: {...}                  # the thesis' values, for the report
//   quick: {...}                      # overrides merged over the above by `--quick`
//
// Reading validates the generic schema; the kind validates methods, params and reference.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "sextant/recordings/recording.hpp"

namespace sextant {

/// One sweep axis: its name and values (scalars or small sequences), in file order.
struct SweepAxis {
  std::string name;
  std::vector<YAML::Node> values;
};

enum class DatasetSource { kNone, kSynthetic, kFolder };

struct DatasetConfig {
  DatasetSource source = DatasetSource::kNone;
  std::filesystem::path
      path;  ///< folder (uos, KITTI, scans) or recording when source = folder; relative to the config file
  /// source folder with a recording: its topic, start, duration and every (the CLI's --topic, …)
  RecordingSelection recording;
  YAML::Node campus;  ///< synthetic campus settings (synth::CampusSettings), may be null
  /// source folder: an odometry simulated from the folder's reference with these settings (the
  /// campus' `odometry:` block, synth::OdometrySettings) and `seed`; null: the folder's own odometry
  YAML::Node simulated_odometry;
  /// A folder whose odometry is simulated (a `simulated_odometry:` map, checked by the reader).
  bool simulates_odometry() const { return simulated_odometry.IsMap(); }
  std::uint64_t seed = 1;  ///< generator seed of the synthetic campus or of the simulated odometry
  YAML::Node node;         ///< the whole block, for the resolved run config
};

struct MethodConfig {
  std::string name;  ///< label in tables and results
  YAML::Node node;   ///< the whole method map (kind-specific keys)
};

/// The most runs one experiment may plan (methods × sweep points × repetitions): a larger plan is an
/// InputError naming its axes, before anything is allocated.
inline constexpr std::uint64_t kMaxRuns = 1000000;

struct ExperimentConfig {
  std::string file;  ///< path of the YAML file, for error messages
  std::string name;
  std::string kind;
  std::string title;
  std::string thesis;  ///< where in the thesis (section, tables, figures)
  std::string description;
  std::uint64_t seed = 1;
  int repetitions = 1;  ///< ≥ 1
  bool quick = false;   ///< the quick overrides were applied
  DatasetConfig dataset;
  std::vector<MethodConfig> methods;  ///< at least one
  std::vector<SweepAxis> sweep;
  std::vector<std::string> metrics;
  YAML::Node params;     ///< map or null
  YAML::Node reference;  ///< map or null
  YAML::Node effective;  ///< the document after applying `quick` (without the quick block)
};

/// Reads and validates the generic schema; throws InputError (file, line, key) on any problem.
/// With `quick`, the `quick:` block is merged over the document first (maps merge, other values
/// replace), so the override's keys are validated like the originals.
ExperimentConfig read_experiment_config(const std::filesystem::path& file, bool quick);
/// Same from an already loaded document (`file` names it in errors).
ExperimentConfig parse_experiment_config(const YAML::Node& document, const std::string& file, bool quick);

/// The sweep axis `name` of `config`; nullptr when it has none.
const SweepAxis* find_axis(const ExperimentConfig& config, const std::string& name);

/// The YAML files under `folder` whose name matches eNN_*.yaml, sorted.
std::vector<std::filesystem::path> list_experiment_configs(const std::filesystem::path& folder);

}  // namespace sextant
