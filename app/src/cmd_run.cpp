// `sextant run <config.yaml>...`: executes experiment configs into results/<experiment>/.
#include <iostream>

#include "commands.hpp"
#include "number_options.hpp"
#include "sextant/experiments/runner.hpp"

namespace sextant::cli {

void add_run_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("run", "Run experiment configs (skips runs already in the results)");
  struct Args {
    std::vector<std::string> configs;
    std::string results = "results";
    std::string cache;
    std::string shard = "1/1";
    int jobs = 0;
    bool quick = false;
    bool no_progress = false;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("configs", args->configs, "experiment YAML files")->required()->check(CLI::ExistingFile);
  cmd->add_option("--results", args->results, "results root: <results>/<experiment>/ is written");
  cmd->add_option("--cache", args->cache, "dataset cache folder (default <results>/_cache)");
  cmd->add_option("--jobs,-j", args->jobs, "worker threads (0 = all)")->check(worker_threads());
  cmd->add_option("--shard", args->shard, "run only the slice i/n of the runs (1-based, e.g. 3/8)");
  cmd->add_flag("--quick", args->quick, "apply each config's quick: overrides (fewer scans and repetitions)");
  cmd->add_flag("--no-progress", args->no_progress, "no progress bar");
  cmd->callback([&exit_code, args] {
    exit_code = guarded([&] {
      RunnerOptions options;
      options.results_root = args->results;
      options.cache_root = args->cache;
      options.jobs = args->jobs;
      options.shard = parse_shard(args->shard);
      options.quick = args->quick;
      options.progress = !args->no_progress && verbosity() != Verbosity::kQuiet;
      int status = 0;
      for (const auto& config : args->configs) {
        const RunnerSummary s = run_experiment(config, options);
        std::cout << s.experiment << ": " << s.executed << " runs executed, " << s.skipped
                  << " already done, " << s.failed << " failed (" << s.in_shard << " in this shard of "
                  << s.total << ") in " << s.seconds << " s → " << s.folder.string() << "\n";
        if (s.failed > 0) status = 1;
      }
      return status;
    });
  });
}

}  // namespace sextant::cli
