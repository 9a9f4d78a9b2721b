// E18 end to end: the shipped config → results → report, with the thesis' exact values.
#include <cmath>
#include <cstdlib>

#include <gtest/gtest.h>

#include "sextant/experiments/report.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/experiments/runner.hpp"
#include "test_helpers.hpp"

namespace sextant {
namespace {

using test::TempDir;

const std::filesystem::path kE18Config =
    std::filesystem::path(SEXTANT_SOURCE_DIR) / "experiments" / "e18_metric_examples.yaml";

TEST(E18, ResultsAndReportHoldTheThesisValues) {
  TempDir tmp;
  const RunnerSummary s = test::run_quick(kE18Config, tmp / "results", false);
  ASSERT_EQ(s.executed, 10u);
  ASSERT_EQ(s.failed, 0u);

  std::map<std::string, double> got;  // "<method>/<example>" → value
  for (const auto& row : read_rows(s.folder / kRunsJsonl).rows)
    got[row.method + "/" + row.point.at("example")] = row.value("translation");
  EXPECT_DOUBLE_EQ(got["wulf/1d_case1"], 1.5);
  EXPECT_DOUBLE_EQ(got["wulf/1d_case2"], 0.5);
  EXPECT_DOUBLE_EQ(got["wulf/1d_case3"], 0.5);
  EXPECT_NEAR(got["wulf/2d_case1"], std::sqrt(16.0 / 3.0), 1e-12);
  EXPECT_NEAR(got["wulf/2d_case2"], std::sqrt(4.0 / 3.0), 1e-12);
  EXPECT_NEAR(got["kummerle/1d_case1"], std::sqrt(6.0), 1e-12);
  EXPECT_NEAR(got["kummerle/1d_case2"], std::sqrt(2.0 / 3.0), 1e-12);
  EXPECT_NEAR(got["kummerle/1d_case3"], std::sqrt(1.0 / 3.0), 1e-12);
  EXPECT_NEAR(got["kummerle/2d_case1"], 4.0, 1e-12);
  EXPECT_NEAR(got["kummerle/2d_case2"], 2.0, 1e-12);

  const ReportSummary r = write_report({tmp / "results"}, tmp / "report");
  EXPECT_EQ(r.experiments, 1u);
  const std::string t61 = test::read_text(tmp / "report" / "e18_metric_examples" / "table_6_1.md");
  const std::string t62 = test::read_text(tmp / "report" / "e18_metric_examples" / "table_6_2.md");
  // ours | thesis side by side: "1.50 | 1.50 | 2.45 | 2.45".
  EXPECT_NE(t61.find("1d_case1 | 1.50 | 1.50 | 2.45 | 2.45"), std::string::npos) << t61;
  EXPECT_NE(t61.find("1d_case3 | 0.50 | 0.50 | 0.58 | 0.58"), std::string::npos) << t61;
  EXPECT_NE(t62.find("2d_case1 | 2.31 | 2.31 | 4.00 | 4.00"), std::string::npos) << t62;
  EXPECT_TRUE(std::filesystem::exists(tmp / "report" / "e18_metric_examples" / "table_6_1.tex"));
  EXPECT_TRUE(std::filesystem::exists(tmp / "report" / "e18_metric_examples" / "table_6_2.csv"));
  EXPECT_EQ(r.figures, 2u);
  EXPECT_TRUE(std::filesystem::exists(tmp / "report" / "e18_metric_examples" / "examples_table_6_1.svg"));
  const std::string html = test::read_text(r.index_html);
  EXPECT_NE(html.find("e18_metric_examples/examples_table_6_2.svg"), std::string::npos);
  EXPECT_NE(html.find("holds"), std::string::npos);
  EXPECT_EQ(html.find("does not hold"), std::string::npos) << "every E18 claim must hold";
}

TEST(E18, ReportRendersInHeadlessChromium) {
  const std::filesystem::path script =
      std::filesystem::path(SEXTANT_SOURCE_DIR) / "scripts" / "check_report_html.sh";
  ASSERT_TRUE(std::filesystem::exists(script)) << "scripts/check_report_html.sh is not in the tree";
  ASSERT_EQ(std::system("command -v chromium >/dev/null 2>&1"), 0)
      << "chromium is not installed: scripts/test.sh installs it (apt-get install chromium)";
  TempDir tmp;
  RunnerOptions o;
  o.results_root = tmp / "results";
  o.progress = false;
  run_experiment(kE18Config, o);
  const ReportSummary r = write_report({tmp / "results"}, tmp / "report");
  const std::string command = "'" + script.string() + "' '" + r.index_html.string() + "'";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
}

}  // namespace
}  // namespace sextant
