// The `sextant` command line: one subcommand per file under cli/.
#include <iostream>

#include "commands.hpp"

namespace sextant::cli {

int guarded(const std::function<int()>& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    std::cerr << "sextant: error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace sextant::cli

int main(int argc, char** argv) {
  using namespace sextant::cli;
  CLI::App app{"Sextant: reproduces the experiments of a 2012 thesis on 3D LiDAR SLAM"};
  app.require_subcommand(1);
  int exit_code = 0;
  // One line per subcommand (keep sorted).
  add_convert_command(app, exit_code);
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
  CLI11_PARSE(app, argc, argv);
  return exit_code;
}
