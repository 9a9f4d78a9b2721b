#pragma once
// `sextant slurm`: a sweep spread over a Slurm job array. Task k of an N-task array runs the
// deterministic shard k/N of every config (`sextant run … --shard k/N`, see select_shard) into its
// own results root; a merge job (`--dependency=afterok:<array>`) merges the shard roots into the
// results root and writes the report. Every run keeps its own key and seed, so the merged results
// do not depend on N. The two sbatch scripts are plain, commented bash, meant to be read and edited.
//
// Layout under the results root R:
//   R/_shards/<k>-of-<N>/<experiment>/   shard k's results (runs.jsonl, …)
//   R/_slurm/array.sbatch, merge.sbatch  the scripts; R/_slurm/logs/ their output; R/_slurm/jobs the ids
//   R/_cache/                            the generated datasets, shared by the tasks
//   R/<experiment>/                      the merged results (what `sextant report` reads)
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace sextant {

struct SlurmOptions {
  std::vector<std::filesystem::path> configs;  ///< experiment configs (absolute paths)
  std::string name;                            ///< job name stem: the experiment's name, or "reproduce"
  std::size_t array_size = 4;                  ///< N: tasks in the array = shards
  std::string partition, time, mem;            ///< #SBATCH --partition / --time / --mem (empty: omitted)
  int cpus_per_task = 1;                       ///< #SBATCH --cpus-per-task; the runner's --jobs
  bool quick = false;                          ///< the configs' quick profile
  std::filesystem::path results;               ///< results root R (absolute)
  std::filesystem::path report;                ///< report folder (absolute)
  std::filesystem::path sextant;               ///< the `sextant` binary the jobs run (absolute)
  std::filesystem::path workdir;               ///< the jobs' working folder (#SBATCH --chdir)

  bool valid(std::string* why) const;
};

/// R/_slurm: the scripts, their logs and the recorded job ids.
std::filesystem::path slurm_folder(const SlurmOptions& options);
/// R/_shards/<k>-of-<N> (k 1-based): the results root of shard k.
std::filesystem::path shard_root(const SlurmOptions& options, std::size_t k);

/// The array job: `#SBATCH --array=1-N`, task k runs `sextant run <configs> --shard k/N`.
std::string array_script(const SlurmOptions& options);
/// The merge job: `sextant merge <shard roots> --out R` then `sextant report R --out <report>`.
std::string merge_script(const SlurmOptions& options);

/// Per shard (1-based), whether its results are complete: the runner's own test of what is finished
/// (plan_experiment: a successful row for every run of the shard, for every config).
struct ShardState {
  std::size_t shard = 0;  ///< 1-based
  std::size_t runs = 0;   ///< runs of this shard over all configs
  std::size_t finished = 0;
  bool complete() const { return finished == runs; }
};
std::vector<ShardState> shard_states(const SlurmOptions& options);

/// "1-4", "3", "2,4-6": an sbatch --array index list for the given 1-based shard numbers (sorted).
std::string array_indices(const std::vector<std::size_t>& shards);

}  // namespace sextant
