#include "sextant/experiments/slurm.hpp"

#include <cctype>
#include <sstream>

#include "sextant/core/error.hpp"
#include "sextant/experiments/runner.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;

/// 'text' for bash, unless it is made only of characters bash leaves alone.
std::string quoted(const std::string& text) {
  bool plain = !text.empty();
  for (const char c : text) {
    const bool ok =
        std::isalnum(static_cast<unsigned char>(c)) || std::string("/._-+=:,@%").find(c) != std::string::npos;
    plain = plain && ok;
  }
  if (plain) return text;
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string quoted(const fs::path& path) {
  return quoted(path.string());
}

/// The #SBATCH header both scripts share.
std::string header(const SlurmOptions& o, const std::string& job, const std::string& log_pattern,
                   const std::string& purpose) {
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# " << purpose << "\n"
    << "# Written by `sextant slurm`; edit freely (`sextant slurm … --resume` keeps an existing script).\n"
    << "#SBATCH --job-name=" << job << "\n"
    << "#SBATCH --chdir=" << quoted(o.workdir) << "\n"
    << "#SBATCH --output=" << quoted(slurm_folder(o) / "logs" / log_pattern) << "\n";
  if (!o.partition.empty()) s << "#SBATCH --partition=" << o.partition << "\n";
  if (!o.time.empty()) s << "#SBATCH --time=" << o.time << "\n";
  if (!o.mem.empty()) s << "#SBATCH --mem=" << o.mem << "\n";
  return s.str();
}

}  // namespace

bool SlurmOptions::valid(std::string* why) const {
  const auto fail = [why](const std::string& text) {
    if (why) *why = text;
    return false;
  };
  if (configs.empty()) return fail("no experiment configs");
  if (array_size < 1 || array_size > 100000) return fail("--array-size must be between 1 and 100000");
  if (cpus_per_task < 1) return fail("--cpus-per-task must be ≥ 1");
  if (!results.is_absolute() || !report.is_absolute() || !sextant.is_absolute() || !workdir.is_absolute())
    return fail("the results, report, binary and working folder must be absolute paths");
  for (const std::string* value : {&partition, &time, &mem}) {
    for (const char c : *value) {
      if (std::isspace(static_cast<unsigned char>(c)) || c == '\'' || c == '"' || c == '\\')
        return fail("'" + *value + "': no spaces or quotes in --partition, --time or --mem");
    }
  }
  return true;
}

fs::path slurm_folder(const SlurmOptions& options) {
  return options.results / "_slurm";
}

fs::path shard_root(const SlurmOptions& options, std::size_t k) {
  return options.results / "_shards" / (std::to_string(k) + "-of-" + std::to_string(options.array_size));
}

std::string array_script(const SlurmOptions& o) {
  const std::string n = std::to_string(o.array_size);
  std::ostringstream s;
  s << header(o, "sextant-" + o.name, "%x-%A_%a.out",
              "Slurm job array: task k of " + n + " runs the shard k/" + n + " of the runs of " +
                  (o.configs.size() == 1 ? "the experiment"
                                         : std::to_string(o.configs.size()) + " experiments") +
                  ".")
    << "#SBATCH --array=1-" << n << "\n"
    << "#SBATCH --ntasks=1\n"
    << "#SBATCH --cpus-per-task=" << o.cpus_per_task << "\n"
    << "set -euo pipefail\n\n"
    << "k=${SLURM_ARRAY_TASK_ID:?run this script with sbatch}\n"
    << "# Shard k holds the runs whose index in the plan is ≡ k−1 (mod " << n
    << "); each keeps its own seed.\n"
    << "# A re-run skips the runs already in the shard's runs.jsonl (the runner's resume).\n"
    << "exec " << quoted(o.sextant) << " run --no-progress" << (o.quick ? " --quick" : "")
    << " --jobs \"${SLURM_CPUS_PER_TASK:-1}\" \\\n"
    << "  --cache " << quoted(o.results / "_cache") << " \\\n"
    << "  --shard \"$k/" << n << "\" --results " << quoted(o.results / "_shards") << "/\"$k-of-" << n << "\"";
  for (const auto& config : o.configs) s << " \\\n  " << quoted(config);
  s << "\n";
  return s.str();
}

std::string merge_script(const SlurmOptions& o) {
  const std::string n = std::to_string(o.array_size);
  std::ostringstream s;
  s << header(o, "sextant-" + o.name + "-merge", "%x-%j.out",
              "Slurm merge job (submitted with --dependency=afterok:<array job>): merges the " + n +
                  " shards and writes the report.")
    << "#SBATCH --ntasks=1\n"
    << "#SBATCH --cpus-per-task=1\n"
    << "set -euo pipefail\n\n"
    << "shards=()\n"
    << "for k in $(seq 1 " << n << "); do shards+=(" << quoted(o.results / "_shards") << "/\"$k-of-" << n
    << "\"); done\n"
    << quoted(o.sextant) << " merge \"${shards[@]}\" --out " << quoted(o.results) << "\n"
    << quoted(o.sextant) << " report " << quoted(o.results) << " --out " << quoted(o.report) << "\n";
  return s.str();
}

std::vector<ShardState> shard_states(const SlurmOptions& options) {
  std::string why;
  if (!options.valid(&why)) throw InputError("options", "", why);
  std::vector<ShardState> states(options.array_size);
  for (std::size_t k = 0; k < states.size(); ++k) states[k].shard = k + 1;
  RunnerOptions runner;
  runner.results_root = options.results;
  runner.shard = Shard{0, options.array_size};
  runner.quick = options.quick;
  for (const auto& config : options.configs) {
    const auto plans =
        plan_shards(config, runner, [&](const Shard& shard) { return shard_root(options, shard.index + 1); });
    for (std::size_t k = 0; k < states.size(); ++k) {
      states[k].runs += plans[k].in_shard;
      states[k].finished += plans[k].finished;
    }
  }
  return states;
}

std::string array_indices(const std::vector<std::size_t>& shards) {
  std::string out;
  for (std::size_t i = 0; i < shards.size();) {
    std::size_t j = i;
    while (j + 1 < shards.size() && shards[j + 1] == shards[j] + 1) ++j;
    out += (out.empty() ? "" : ",") + std::to_string(shards[i]);
    if (j > i) out += "-" + std::to_string(shards[j]);
    i = j + 1;
  }
  return out;
}

}  // namespace sextant
