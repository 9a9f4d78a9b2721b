#pragma once
// Executes an experiment: validates its config, expands it into runs, skips those already in
// results/<experiment>/runs.jsonl, runs the rest in parallel (TBB) and appends one JSON line per
// finished run, then rewrites runs.csv and provenance.json atomically. A process killed mid-sweep
// loses at most the runs in flight; the next invocation completes the rest.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "sextant/experiments/run_plan.hpp"

namespace sextant {

struct RunnerOptions {
  std::filesystem::path results_root = "results";  ///< results/<experiment>/ is written
  std::filesystem::path cache_root;                ///< generated datasets; empty = <results_root>/_cache
  int jobs = 0;                                    ///< worker threads; 0 = all hardware threads
  Shard shard;                                     ///< the slice of runs to execute
  bool quick = false;                              ///< apply the config's `quick:` overrides
  bool progress = true;                            ///< progress bar on a terminal (stderr)
  std::size_t max_runs = 0;                        ///< stop after this many new runs (0 = all); for tests

  bool valid(std::string* why) const;
};

struct RunnerSummary {
  std::string experiment;
  std::filesystem::path folder;  ///< results/<experiment>
  std::size_t total = 0;         ///< runs in the plan (expand_runs)
  std::size_t in_shard = 0;      ///< runs of this shard
  std::size_t skipped = 0;       ///< already finished
  std::size_t executed = 0;      ///< ran now
  std::size_t failed = 0;        ///< ran now and threw (recorded with ok = false, retried next time)
  double seconds = 0.0;
  std::vector<std::string> warnings;  ///< e.g. "…/runs.jsonl:7: unreadable line skipped …" (also logged)
};

/// Runs one experiment config. Throws InputError for a bad config or option.
RunnerSummary run_experiment(const std::filesystem::path& config_file, const RunnerOptions& options);

/// What run_experiment would do now, without running or writing anything: how many runs of the
/// shard are already finished in <results_root>/<experiment>/runs.jsonl (the same test its resume
/// uses: a successful row with the run's key). `sextant slurm --resume` asks this per shard.
struct RunnerPlan {
  std::string experiment;
  std::filesystem::path folder;  ///< results/<experiment>
  std::size_t total = 0;         ///< runs in the plan (expand_runs)
  std::size_t in_shard = 0;      ///< runs of this shard
  std::size_t finished = 0;      ///< of those, finished successfully
  bool complete() const { return finished == in_shard; }
};
RunnerPlan plan_experiment(const std::filesystem::path& config_file, const RunnerOptions& options);
/// plan_experiment for every shard k/n, n = options.shard.count, the config read and expanded once;
/// shard k's results are looked up under results_root(shard k).
std::vector<RunnerPlan> plan_shards(const std::filesystem::path& config_file, const RunnerOptions& options,
                                    const std::function<std::filesystem::path(const Shard&)>& results_root);

/// File names inside results/<experiment>/.
inline constexpr const char* kRunsJsonl = "runs.jsonl";
inline constexpr const char* kRunsCsv = "runs.csv";
inline constexpr const char* kEffectiveConfig = "experiment.yaml";
/// provenance.json, or provenance.shard-<i>-of-<n>.json for a shard.
std::string provenance_file_name(const Shard& shard);

}  // namespace sextant
