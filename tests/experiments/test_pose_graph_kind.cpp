// The `pose_graph` run kind (E20): the quick profile end to end — rows of the odometry + graph
// method and of the filters, the tables' dimensions, figures, TUM files and claims — and config
// validation.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/core/io/trajectory_io.hpp"
#include "sextant/experiments/experiment_config.hpp"
#include "sextant/experiments/report.hpp"
#include "sextant/experiments/run_kind.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/experiments/runner.hpp"
#include "test_helpers.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

/// Data rows of a Markdown table (lines starting with '|' after the header separator).
std::size_t table_rows(const std::string& md) {
  std::size_t rows = 0;
  bool body = false;
  std::size_t start = 0;
  while (start < md.size()) {
    const std::size_t end = std::min(md.find('\n', start), md.size());
    const std::string line = md.substr(start, end - start);
    if (line.rfind("| :", 0) == 0 || line.rfind("|---", 0) == 0)
      body = true;
    else if (body && line.rfind("|", 0) == 0)
      ++rows;
    else if (body)
      body = false;
    start = end + 1;
  }
  return rows;
}

TEST(PoseGraphKind, E20QuickProfileBuildsTheGraphAndComparesTheFilters) {
  TempDir tmp;
  const RunnerSummary s = test::run_quick(test::experiments_dir() / "e20_pose_graph.yaml", tmp / "results");
  ASSERT_EQ(s.executed, 5u);  // mlndt + ekf, ukf, ckf, seif; one repetition
  ASSERT_EQ(s.failed, 0u);
  constexpr std::size_t kScans = 95;
  for (const auto& row : read_rows(s.folder / kRunsJsonl).rows) {
    ASSERT_TRUE(row.ok) << row.error;
    if (row.method == "mlndt") {
      EXPECT_EQ(row.value("scans"), double(kScans));
      for (const char* p : {"chained_", "graph_", "false_robust_", "false_plain_"}) {
        EXPECT_EQ(row.series.at(std::string(p) + "trajectory").size(), 12 * kScans) << p;
        EXPECT_EQ(row.series.at(std::string(p) + "ate_errors").size(), kScans) << p;
        EXPECT_TRUE(std::isfinite(row.value(std::string(p) + "ate_m"))) << p;
        EXPECT_TRUE(std::isfinite(row.value(std::string(p) + "kummerle_rotation_deg"))) << p;
      }
      // The chain and the graph start at the true first pose (the graph's gauge).
      for (std::size_t k = 0; k < 12; ++k) {
        EXPECT_EQ(row.series.at("chained_trajectory")[k], row.series.at("truth")[k]);
        EXPECT_NEAR(row.series.at("graph_trajectory")[k], row.series.at("truth")[k], 1e-12);
      }
      // The quick stretch comes back to its start (the first loop, ≈ scan 80): candidates exist.
      EXPECT_GE(row.value("candidates"), 1.0);
      EXPECT_EQ(row.series.at("closure_i").size(), std::size_t(row.value("candidates")));
      EXPECT_EQ(row.value("false_closures"), 1.0);
      EXPECT_EQ(row.value("graph_solve_ok"), 1.0);
      EXPECT_LE(row.value("graph_solve_final_cost"), row.value("graph_solve_initial_cost"));
    } else {
      const std::size_t n = row.method == "ukf" || row.method == "ckf" ? 30 : kScans;
      EXPECT_EQ(row.series.at("filter_trajectory").size(), 12 * n) << row.method;
      EXPECT_TRUE(std::isfinite(row.value("filter_ate_m"))) << row.method;
    }
  }

  const ReportSummary r = write_report({tmp / "results"}, tmp / "report");
  ASSERT_EQ(r.experiments, 1u);
  ASSERT_TRUE(r.failed.empty()) << r.failed.front();
  const fs::path dir = tmp / "report" / "e20_pose_graph";
  EXPECT_EQ(table_rows(test::read_text(dir / "metrics.md")), 8u);     // 4 graph trajectories + 4 filters
  EXPECT_EQ(table_rows(test::read_text(dir / "metrics_30.md")), 4u);  // chained, graph, ukf, ckf
  EXPECT_EQ(table_rows(test::read_text(dir / "loop_closures.md")), 1u);
  for (const char* svg : {"trajectories.svg", "false_closure.svg", "position_error.svg"})
    EXPECT_TRUE(fs::exists(dir / svg)) << svg;
  for (const char* tum : {"trajectory_truth.tum", "trajectory_chained.tum", "trajectory_graph.tum"}) {
    const Trajectory t = read_tum_trajectory(dir / tum);
    EXPECT_EQ(t.size(), kScans) << tum;
  }
  const std::string html = test::read_text(r.index_html);
  for (const char* claim : {"Loop closure reduces ATE vs chained odometry", "keeps a false loop closure",
                            "does wreck the map", "The graph solve is cheap"})
    EXPECT_NE(html.find(claim), std::string::npos) << claim;
}

TEST(PoseGraphKind, ConfigProblemsNameTheKey) {
  const auto check = [](const std::string& yaml, const std::string& expected) {
    const ExperimentConfig c = parse_experiment_config(YAML::Load(yaml), "e20.yaml", false);
    try {
      run_kind_registry().create(c.kind)->validate(c);
      ADD_FAILURE() << "accepted: " << yaml;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  const std::string head = "name: e20\nkind: pose_graph\ndataset: {source: synthetic}\n";
  const std::string methods =
      "methods:\n  - {name: m, matcher: mlndt, sampler: gbs}\n  - {name: e, filter: ekf}\n";
  check(head + methods + "params: {loop_closure: {radius: 5, radious: 3}}\n", "radious");
  check(head + methods + "params: {graph: {loss: tukey}}\n", "tukey");
  check(head + methods + "params: {guess: sideways}\n", "sideways");
  check(head + "methods:\n  - {name: e, filter: ekf}\n", "exactly one method with a matcher");
  check(head + methods + "params: {scans: 5000}\n", "scans");
}

}  // namespace
}  // namespace sextant
