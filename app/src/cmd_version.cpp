// `sextant version`: the versions of Sextant and of the libraries it was built against.
#include <iostream>

#include "commands.hpp"
#include "sextant/pipeline/provenance.hpp"

namespace sextant::cli {

void add_version_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("version", "Print the versions of Sextant and its libraries");
  cmd->callback([&exit_code] {
    exit_code = guarded([] {
      std::cout << version_line() << "\n"
                << "libraries: " << library_versions_json() << "\n";
      return 0;
    });
  });
}

}  // namespace sextant::cli
