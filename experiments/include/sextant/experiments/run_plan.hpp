#pragma once
// Expanding an experiment into runs: methods × sweep points (cartesian product) × repetitions.
// Each run's resolved config is hashed (canonical JSON, FNV-1a) into its key, so results are
// found again whatever the order, the shard or the machine.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "sextant/experiments/experiment_config.hpp"

namespace sextant {

struct RunSpec {
  std::size_t index = 0;  ///< position in the expansion (method-major, then sweep, then repetition)
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

/// All runs of an experiment, in a deterministic order.
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
