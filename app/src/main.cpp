// The `sextant` command line: one subcommand per file in app/src/. Exit status, the same in every
// subcommand: 0 success, 1 a runtime error (bad input, a failed run), 2 a usage error, 3 a result that
// is not converged or not trusted (`match`).
#include <iostream>

#include "commands.hpp"
#include "sextant/pipeline/provenance.hpp"

namespace sextant::cli {
namespace {

Verbosity g_verbosity = Verbosity::kNormal;

}  // namespace

Verbosity verbosity() {
  return g_verbosity;
}
void set_verbosity(Verbosity v) {
  g_verbosity = v;
}

std::string version_line() {
  const GitState git = current_git_state();
  return "sextant " + sextant_version() + " (commit " + git.sha.substr(0, 12) + (git.dirty ? ", dirty" : "") +
         ")";
}

int guarded(const std::function<int()>& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    std::cerr << "sextant: error: " << e.what() << "\n";
    return kExitRuntimeError;
  }
}

}  // namespace sextant::cli

int main(int argc, char** argv) {
  using namespace sextant::cli;
  CLI::App app{"Sextant: reproduces the experiments of a 2012 thesis on 3D LiDAR SLAM"};
  app.require_subcommand(1);
  app.fallthrough();  // the global flags below also after the subcommand: `sextant match a b -q`
  app.set_version_flag(
      "--version", [] { return version_line(); }, "Print the version and exit");
  auto* quiet = app.add_flag_callback(
      "-q,--quiet", [] { set_verbosity(Verbosity::kQuiet); },
      "Print only results and errors (no progress, notes or summaries)");
  app.add_flag_callback(
         "-v,--verbose", [] { set_verbosity(Verbosity::kVerbose); },
         "Print the detail behind the results (iterations, steps)")
      ->excludes(quiet);
  int exit_code = 0;
  // One line per subcommand (keep sorted).
  add_convert_command(app, exit_code);
  add_eval_command(app, exit_code);
  add_info_command(app, exit_code);
  add_match_command(app, exit_code);
  add_merge_command(app, exit_code);
  add_odometry_command(app, exit_code);
  add_report_command(app, exit_code);
  add_reproduce_command(app, exit_code);
  add_run_command(app, exit_code);
  add_slurm_command(app, exit_code);
  add_synth_command(app, exit_code);
  add_version_command(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help prints and succeeds; every other parse error is a usage error: exit 2 (README, "Exit
    // status"), whatever CLI11's own code for it is.
    const int cli11 = app.exit(e);
    return cli11 == 0 ? 0 : kExitUsage;
  }
  return exit_code;
}
