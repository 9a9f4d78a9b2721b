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
      const MergeSummary merged = merge_results({inputs->begin(), inputs->end()}, *out);
      for (const MergedExperiment& e : merged.experiments) {
        std::cout << "merge: " << e.name << ": " << e.rows << " rows from " << e.inputs << " folder"
                  << (e.inputs == 1 ? "" : "s") << "; " << e.expected - e.missing << " of " << e.expected
                  << " runs present, " << e.missing << " missing, " << e.duplicated
                  << " in more than one input\n";
        constexpr std::size_t kNamed = 10;
        for (std::size_t i = 0; i < e.missing_runs.size() && i < kNamed; ++i)
          std::cout << "  missing: " << e.missing_runs[i] << "\n";
        if (e.missing_runs.size() > kNamed)
          std::cout << "  … and " << e.missing_runs.size() - kNamed << " more missing\n";
      }
      std::cout << "merge: " << merged.rows << " rows → " << *out << "\n";
      return 0;
    });
  });
}

}  // namespace sextant::cli
