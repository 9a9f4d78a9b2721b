// `sextant merge <results>... --out <dir>`: combines result roots (e.g. one per shard).
#include <iostream>

#include "commands.hpp"
#include "sextant/experiments/report.hpp"

namespace sextant::cli {

void add_merge_command(CLI::App& app, int& exit_code) {
  auto* cmd =
      app.add_subcommand("merge", "Merge result roots (e.g. shards) into one, deduplicated by run key");
  auto inputs = std::make_shared<std::vector<std::string>>();
  auto out = std::make_shared<std::string>();
  cmd->add_option("inputs", *inputs, "results roots")->required()->check(CLI::ExistingDirectory);
  cmd->add_option("--out,-o", *out, "merged results root")->required();
  cmd->callback([&exit_code, inputs, out] {
    exit_code = guarded([&] {
      const std::size_t rows = merge_results({inputs->begin(), inputs->end()}, *out);
      std::cout << "merge: " << rows << " rows → " << *out << "\n";
      return 0;
    });
  });
}

}  // namespace sextant::cli
