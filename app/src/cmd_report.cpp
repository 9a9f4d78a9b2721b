// `sextant report <results>... --out <dir>`: tables, figures, claims and index.html from results.
#include <iostream>

#include "commands.hpp"
#include "sextant/experiments/report.hpp"

namespace sextant::cli {

void add_report_command(CLI::App& app, int& exit_code) {
  auto* cmd =
      app.add_subcommand("report", "Write the report (Markdown/LaTeX/CSV tables, SVG figures, index.html)");
  auto results = std::make_shared<std::vector<std::string>>();
  auto out = std::make_shared<std::string>("report");
  cmd->add_option("results", *results, "results roots (several: shards are merged by run key)")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--out,-o", *out, "output folder");
  cmd->callback([&exit_code, results, out] {
    exit_code = guarded([&] {
      const ReportSummary s = write_report({results->begin(), results->end()}, *out);
      std::cout << "report: " << s.experiments << " experiments, " << s.tables << " tables, " << s.figures
                << " figures, " << s.views << " 3D views, " << s.claims << " claims → "
                << s.index_html.string() << "\n";
      for (const auto& failure : s.failed) std::cerr << "sextant: error: report of " << failure << "\n";
      return s.failed.empty() ? 0 : 1;
    });
  });
}

}  // namespace sextant::cli
