// `sextant slurm <config.yaml|reproduce>`: writes (and with --submit submits) a Slurm job array
// running one shard of the runs per task, plus a merge job that waits for it (afterok), merges the
// shards and writes the report. `--resume` re-submits only the shards whose results are incomplete.
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include <unistd.h>

#include "commands.hpp"
#include "number_options.hpp"
#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "sextant/experiments/experiment_config.hpp"
#include "sextant/experiments/slurm.hpp"

namespace sextant::cli {
namespace {

namespace fs = std::filesystem;

struct Args {
  std::string target;
  std::size_t array_size = 4;
  std::string partition, time, mem;
  int cpus_per_task = 1;
  std::string results = "results";
  std::string report = "report";
  std::string experiments;
  bool quick = false;
  bool submit = false;
  bool resume = false;
};

struct Captured {
  int status = 0;
  std::string output;  ///< stdout and stderr
};

Captured capture(const std::string& command) {
  Captured c;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) throw InputError(command, "", "cannot start the command");
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) c.output.append(buffer.data(), n);
  c.status = ::pclose(pipe);
  return c;
}

/// Submits with `sbatch --parsable` and returns the job id ("12" of "12;cluster").
std::string sbatch(const std::string& arguments) {
  const Captured c = capture("sbatch --parsable " + arguments);
  const std::string id = c.output.substr(0, c.output.find_first_of(";\n"));
  if (c.status != 0 || id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
    throw InputError("sbatch", "", "submission failed (sbatch " + arguments + "): " + c.output);
  return id;
}

/// Jobs recorded by the last submission (R/_slurm/jobs: "array <id>" and "merge <id>").
std::map<std::string, std::string> recorded_jobs(const fs::path& file) {
  std::map<std::string, std::string> jobs;
  std::ifstream in(file);
  std::string role, id;
  while (in >> role >> id) jobs[role] = id;
  return jobs;
}

/// squeue's "<state> <reason>" of a job still queued or running; empty once it has ended.
std::string queued_state(const std::string& job) {
  const Captured c = capture("squeue -h -o '%T %r' -j " + job);
  if (c.status != 0 || c.output.find_first_not_of(" \n") == std::string::npos) return "";
  return c.output.substr(0, c.output.find('\n'));
}

std::string resume_command(const Args& a, const fs::path& sextant) {
  std::string s = sextant.string() + " slurm " + a.target + (a.quick ? " --quick" : "") + " --array-size " +
                  std::to_string(a.array_size);
  if (!a.partition.empty()) s += " --partition " + a.partition;
  if (!a.time.empty()) s += " --time " + a.time;
  if (!a.mem.empty()) s += " --mem " + a.mem;
  if (a.cpus_per_task != 1) s += " --cpus-per-task " + std::to_string(a.cpus_per_task);
  if (!a.experiments.empty()) s += " --experiments " + a.experiments;
  return s + " --results " + a.results + " --report " + a.report + " --resume --submit";
}

SlurmOptions options_from(const Args& a) {
  SlurmOptions o;
  if (a.target == "reproduce") {
    const fs::path folder = a.experiments.empty() ? default_experiments_folder() : fs::path(a.experiments);
    for (const auto& config : list_experiment_configs(folder)) o.configs.push_back(fs::absolute(config));
    if (o.configs.empty())
      throw InputError(folder.string(), "", "no experiment configs (eNN_<slug>.yaml) found");
    o.name = "reproduce";
  } else {
    if (!fs::is_regular_file(a.target))
      throw InputError(a.target, "", "not an experiment config (a YAML file) nor 'reproduce'");
    o.configs.push_back(fs::absolute(a.target));
    o.name = read_experiment_config(a.target, a.quick).name;
  }
  o.array_size = a.array_size;
  o.partition = a.partition;
  o.time = a.time;
  o.mem = a.mem;
  o.cpus_per_task = a.cpus_per_task;
  o.quick = a.quick;
  o.results = fs::absolute(a.results);
  o.report = fs::absolute(a.report);
  o.sextant = fs::read_symlink("/proc/self/exe");
  o.workdir = fs::current_path();
  std::string why;
  if (!o.valid(&why)) throw InputError("sextant slurm", "", why);
  return o;
}

int slurm_main(const Args& a) {
  const SlurmOptions o = options_from(a);
  const fs::path folder = slurm_folder(o);
  const fs::path array_file = folder / "array.sbatch", merge_file = folder / "merge.sbatch";
  fs::create_directories(folder / "logs");
  for (const auto& [file, text] :
       {std::pair{array_file, array_script(o)}, std::pair{merge_file, merge_script(o)}}) {
    if (a.resume && fs::exists(file)) {
      std::cout << "kept     " << file.string() << " (as it is, edits included)\n";
    } else {
      write_file_atomically(file, text);
      std::cout << "wrote    " << file.string() << "\n";
    }
  }

  std::vector<std::size_t> shards;  // the array tasks to submit
  std::size_t runs = 0, finished = 0;
  for (const ShardState& s : shard_states(o)) {
    runs += s.runs;
    finished += s.finished;
    if (!a.resume || !s.complete()) shards.push_back(s.shard);
  }
  std::cout << o.name << ": " << runs << " runs in " << o.array_size << " shards (" << o.configs.size()
            << " config" << (o.configs.size() == 1 ? "" : "s") << "), " << finished << " finished\n";
  if (a.resume) {
    std::cout << "resume:  "
              << (shards.empty() ? "every shard is complete; only the merge job is needed"
                  : shards.size() == 1
                      ? "shard " + array_indices(shards) + " of " + std::to_string(o.array_size) +
                            " is missing or incomplete; only it is re-run"
                      : "shards " + array_indices(shards) + " of " + std::to_string(o.array_size) +
                            " are missing or incomplete; only they are re-run")
              << "\n";
  }
  const std::string indices = shards.empty() ? "" : array_indices(shards);
  const std::string array_args = (a.resume ? "--array=" + indices + " " : "") + array_file.string();

  if (!a.submit) {
    std::cout << "submit:  ";
    if (shards.empty()) {
      std::cout << "sbatch " << merge_file.string() << "\n";
    } else {
      std::cout << "jid=$(sbatch --parsable " << array_args << ") && sbatch --dependency=afterok:$jid "
                << merge_file.string() << "\n";
    }
    std::cout << "         (or run this command again with --submit)\n";
    return 0;
  }

  const fs::path jobs_file = folder / "jobs";
  const auto previous = recorded_jobs(jobs_file);
  const auto queued = [&](const char* role) {
    return a.resume && previous.count(role) ? queued_state(previous.at(role)) : std::string();
  };
  if (const std::string state = queued("array"); !state.empty()) {
    throw InputError("sextant slurm --resume", "",
                     "array job " + previous.at("array") + " still has tasks queued or running (" + state +
                         "; squeue -j " + previous.at("array") +
                         "); wait for it to end, or scancel it, then resume");
  }
  if (const std::string state = queued("merge"); !state.empty()) {
    // Pending after its array ended with shards incomplete: its afterok can never be met.
    const bool stranded = state.rfind("PENDING", 0) == 0 &&
                          (state.find("DependencyNeverSatisfied") != std::string::npos || !shards.empty());
    if (!stranded) {
      throw InputError("sextant slurm --resume", "",
                       "merge job " + previous.at("merge") + " is still queued or running (" + state +
                           "); wait for it to end, or scancel it, then resume");
    }
    // A task of its array failed or was cancelled: it would wait forever. Replace it.
    capture("scancel " + previous.at("merge"));
    std::cout << "cancelled the previous merge job " << previous.at("merge")
              << " (it waited for shards that did not finish)\n";
  }
  std::string array_id, merge_id;
  if (!shards.empty()) array_id = sbatch(array_args);
  merge_id = sbatch((array_id.empty() ? "" : "--dependency=afterok:" + array_id + " ") + merge_file.string());
  write_file_atomically(jobs_file,
                        (array_id.empty() ? "" : "array " + array_id + "\n") + "merge " + merge_id + "\n");
  const std::string ids = array_id.empty() ? merge_id : array_id + "," + merge_id;
  if (!array_id.empty()) std::cout << "submitted: array job " << array_id << " (tasks " << indices << ")\n";
  std::cout << "submitted: merge job " << merge_id
            << (array_id.empty() ? "" : " (--dependency=afterok:" + array_id + ")") << "\n";
  std::cout << "watch:   squeue -j " << ids << "     (after the end, with accounting: sacct -j " << ids
            << ")\n"
            << "logs:    " << (folder / "logs").string() << "/\n"
            << "results: " << o.results.string() << " (merged), report: " << o.report.string() << "\n"
            << "resume:  " << resume_command(a, o.sextant) << "\n"
            << "         (after a failed or cancelled task: re-submits only the shards whose results are "
               "missing or "
               "incomplete)\n";
  return 0;
}

}  // namespace

void add_slurm_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "slurm",
      "Write (and --submit) a Slurm job array over the runs of a config or of `reproduce`, plus a merge job");
  auto args = std::make_shared<Args>();
  cmd->add_option("target", args->target, "an experiment config (YAML), or 'reproduce' for every experiment")
      ->required();
  cmd->add_option("--array-size,-n", args->array_size, "tasks in the array (= shards)")
      ->check(whole_number(1, 100000));
  cmd->add_option("--partition,-p", args->partition, "#SBATCH --partition");
  cmd->add_option("--time,-t", args->time, "#SBATCH --time per task (e.g. 01:00:00)");
  cmd->add_option("--mem", args->mem, "#SBATCH --mem per task (e.g. 4G)");
  cmd->add_option("--cpus-per-task,-c", args->cpus_per_task, "#SBATCH --cpus-per-task; the runner's --jobs")
      ->check(whole_number(1));
  cmd->add_option("--results", args->results, "results root: merged results; shards in <results>/_shards");
  cmd->add_option("--report", args->report, "report folder the merge job writes");
  cmd->add_option("--experiments", args->experiments, "folder of eNN_*.yaml configs for 'reproduce'");
  cmd->add_flag("--quick", args->quick, "the quick profile");
  cmd->add_flag("--submit", args->submit, "submit with sbatch and print the job ids");
  cmd->add_flag("--resume", args->resume, "submit only the shards whose results are missing or incomplete");
  cmd->callback([&exit_code, args] { exit_code = guarded([&] { return slurm_main(*args); }); });
}

}  // namespace sextant::cli
