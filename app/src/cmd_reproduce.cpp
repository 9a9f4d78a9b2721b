// `sextant reproduce [--quick]`: every experiment config under experiments/, then the report.
#include <filesystem>
#include <iostream>

#include "commands.hpp"
#include "number_options.hpp"
#include "sextant/core/error.hpp"
#include "sextant/experiments/experiment_config.hpp"
#include "sextant/experiments/report.hpp"
#include "sextant/experiments/runner.hpp"

namespace sextant::cli {

std::filesystem::path default_experiments_folder() {
  if (std::filesystem::is_directory("experiments")) return "experiments";
  return std::filesystem::path(SEXTANT_SOURCE_DIR) / "experiments";
}

void add_reproduce_command(CLI::App& app, int& exit_code) {
  auto* cmd =
      app.add_subcommand("reproduce", "Run every experiment config (eNN_*.yaml) and write the report");
  struct Args {
    std::string experiments;
    std::string results = "results";
    std::string report = "report";
    int jobs = 0;
    bool quick = false;
    bool no_progress = false;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("--experiments", args->experiments,
                  "folder of eNN_*.yaml configs (default: the source tree's experiments/)");
  cmd->add_option("--results", args->results, "results root");
  cmd->add_option("--report", args->report, "report folder");
  cmd->add_option("--jobs,-j", args->jobs, "worker threads (0 = all)")->check(worker_threads());
  cmd->add_flag("--quick", args->quick, "the quick profile (fewer scans and repetitions)");
  cmd->add_flag("--no-progress", args->no_progress, "no progress bar");
  cmd->callback([&exit_code, args] {
    exit_code = guarded([&] {
      const auto folder =
          args->experiments.empty() ? default_experiments_folder() : std::filesystem::path(args->experiments);
      const auto configs = list_experiment_configs(folder);
      if (configs.empty())
        throw InputError(folder.string(), "", "no experiment configs (eNN_<slug>.yaml) found");
      RunnerOptions options;
      options.results_root = args->results;
      options.jobs = args->jobs;
      options.quick = args->quick;
      options.progress = !args->no_progress && verbosity() != Verbosity::kQuiet;
      int status = 0;
      std::size_t not_run = 0;
      for (const auto& config : configs) {
        // One experiment that cannot start (e.g. its dataset folder is missing) does not stop the
        // others: it is named here, counted below, and the exit status says so.
        try {
          const RunnerSummary s = run_experiment(config, options);
          std::cout << s.experiment << ": " << s.executed << " runs executed, " << s.skipped
                    << " already done, " << s.failed << " failed, " << s.seconds << " s\n";
          if (s.failed > 0) status = 1;
        } catch (const InputError& e) {
          std::cerr << "sextant: error: " << config.filename().string() << " not run: " << e.what() << "\n";
          ++not_run;
          status = 1;
        }
      }
      if (not_run > 0)
        std::cerr << "sextant: " << not_run << " of " << configs.size()
                  << " experiments not run (see above)\n";
      const ReportSummary r = write_report({args->results}, args->report);
      std::cout << "report: " << r.experiments << " experiments, " << r.tables << " tables, " << r.figures
                << " figures, " << r.claims << " claims → " << r.index_html.string() << "\n";
      for (const auto& failure : r.failed) std::cerr << "sextant: error: report of " << failure << "\n";
      return r.failed.empty() ? status : 1;
    });
  });
}

}  // namespace sextant::cli
