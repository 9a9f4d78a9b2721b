#pragma once
// Expanding an experiment into runs: methods × sweep points (cartesian product) × repetitions,
// shaped by the experiment's run kind (RunKind::planned_runs). Each run's resolved config is
// hashed (canonical JSON, FNV-1a) into its key, so results are found again whatever the order,
// the shard or the machine.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "sextant/experiments/experiment_config.hpp"

namespace sextant {

struct RunSpec {
  std::size_t index = 0;  ///< position in the plan (method-major, then sweep, then repetition)
  std::string key;        ///< hash of `resolved`
  std::string method;     ///< method name
  std::size_t method_index = 0;
  std::map<std::string, std::string> point;  ///< axis → value label (canonical JSON for non-scalars)
  int repetition = 0;
  std::uint64_t seed = 0;  ///< same for every method at one (sweep point, repetition): paired comparisons
  /// {experiment, kind, dataset, method, point, repetition, seed, params} — an independent copy,
  /// safe to read from the thread that executes the run.
  YAML::Node resolved;
};

/// How RunSpec::point spells a sweep value: a scalar as written, anything else as canonical JSON.
std::string point_label(const YAML::Node& value);

/// The full cartesian product: every method at every sweep point and repetition, in a fixed order.
/// Keys and seeds are decided here, whatever a kind's plan keeps. Not the list of runs: a kind's
/// session may read it for the sweep as a whole (the adaptive starting layer reuses the seeds of
/// runs at every pair), everything that lists, counts, shards or finds runs uses expand_runs.
std::vector<RunSpec> expand_sweep(const ExperimentConfig& config);

/// The runs of an experiment: expand_sweep less the runs its kind leaves out (RunKind::planned_runs;
/// an unknown kind leaves none out), `index` renumbered 0…n−1. The one expansion of the runner,
/// resume, shards, merge, report and `sextant info`, so that their counts agree.
std::vector<RunSpec> expand_runs(const ExperimentConfig& config);

struct Shard {
  std::size_t index = 0;  ///< 0-based
  std::size_t count = 1;  ///< ≥ 1
};

/// Parses "i/n" (1-based i, as in job arrays: 1/4 … 4/4); throws InputError("--shard", ...) when malformed.
Shard parse_shard(const std::string& text);
/// The runs of one shard: run k belongs to shard k mod n. The shards partition the runs exactly.
std::vector<RunSpec> select_shard(const std::vector<RunSpec>& runs, const Shard& shard);

}  // namespace sextant
