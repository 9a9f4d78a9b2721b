// `sextant version`: the versions of Sextant and of the libraries it was built against.
#include <Eigen/Core>
#include <iostream>

#include "commands.hpp"

namespace sextant::cli {

void add_version_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("version", "Print the versions of Sextant and its libraries");
  cmd->callback([&exit_code] {
    exit_code = guarded([] {
      std::cout << "sextant 0.1.0\n"
                << "eigen " << EIGEN_WORLD_VERSION << "." << EIGEN_MAJOR_VERSION << "." << EIGEN_MINOR_VERSION
                << "\n";
      return 0;
    });
  });
}

}  // namespace sextant::cli
