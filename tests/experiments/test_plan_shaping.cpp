// A run kind shapes its plan (RunKind::planned_runs, issue 24): the registration kind plans an
// adaptive starting layer method once per (f, repetition), since that one run registers every pair
// itself, and leaves every other run, key and seed as the full sweep has it. The runner, resume,
// shards, merge, report and `sextant info` all count that one plan.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <set>

#include "sextant/experiments/experiment_config.hpp"
#include "sextant/experiments/report.hpp"
#include "sextant/experiments/run_plan.hpp"
#include "sextant/experiments/runner.hpp"
#include "test_helpers.hpp"

namespace sextant {
namespace plan_shaping_test {  // named: the tests are a unity build

namespace fs = std::filesystem;

fs::path config_file(const std::string& name) {
  return fs::path(SEXTANT_SOURCE_DIR) / "experiments" / (name + ".yaml");
}

bool is_adaptive(const RunSpec& run) {
  return run.method.find("adaptive") != std::string::npos;
}

/// Checks that `plan` is the sweep less the adaptive runs off the first pair and start layer:
/// the same runs (keys, seeds, points), in the same order, indices renumbered.
void expect_shaped(const std::vector<RunSpec>& sweep, const std::vector<RunSpec>& plan) {
  std::vector<const RunSpec*> expected;
  for (const RunSpec& run : sweep) {
    const auto layer = run.point.find("start_layer");
    if (!is_adaptive(run) ||
        (run.point.at("pair") == "0" && (layer == run.point.end() || layer->second == "2")))
      expected.push_back(&run);
  }
  ASSERT_EQ(plan.size(), expected.size());
  for (std::size_t i = 0; i < plan.size(); ++i) {
    EXPECT_EQ(plan[i].index, i);
    EXPECT_EQ(plan[i].key, expected[i]->key) << i;
    EXPECT_EQ(plan[i].seed, expected[i]->seed) << i;
    EXPECT_EQ(plan[i].method, expected[i]->method) << i;
    EXPECT_EQ(plan[i].point, expected[i]->point) << i;
    EXPECT_EQ(plan[i].repetition, expected[i]->repetition) << i;
  }
}

TEST(PlanShaping, AdaptiveMethodsPlanOneRunPerOtherPointAndRepetition) {
  ExperimentConfig config = read_experiment_config(config_file("e04_init_vs_layer"), true);
  std::vector<RunSpec> sweep = expand_sweep(config), plan = expand_runs(config);
  ASSERT_EQ(sweep.size(), 5u * 15u * 4u * 3u);  // 5 methods × 15 pairs × 4 f × 3 start layers
  // The 3 fixed-layer methods at every point; the 2 adaptive ones once per f.
  EXPECT_EQ(plan.size(), 3u * 15u * 4u * 3u + 2u * 4u);
  expect_shaped(sweep, plan);
  std::map<std::string, std::set<std::string>> adaptive_f;  // method → the f of its runs
  for (const RunSpec& run : plan) {
    if (is_adaptive(run)) {
      EXPECT_TRUE(adaptive_f[run.method].insert(run.point.at("f")).second);
    }
  }
  ASSERT_EQ(adaptive_f.size(), 2u);
  for (const auto& [method, f] : adaptive_f) EXPECT_EQ(f.size(), 4u) << method;

  config.repetitions = 2;  // one run per (f, repetition)
  sweep = expand_sweep(config);
  plan = expand_runs(config);
  EXPECT_EQ(plan.size(), 2u * (3u * 15u * 4u * 3u + 2u * 4u));
  expect_shaped(sweep, plan);

  config.repetitions = 1;  // without a start_layer axis: the first pair alone
  ASSERT_EQ(config.sweep.at(2).name, "start_layer");
  config.sweep.erase(config.sweep.begin() + 2);
  sweep = expand_sweep(config);
  plan = expand_runs(config);
  EXPECT_EQ(plan.size(), 3u * 15u * 4u + 2u * 4u);
  expect_shaped(sweep, plan);
}

TEST(PlanShaping, KindsWithoutAHookPlanTheWholeSweep) {
  const ExperimentConfig config =
      parse_experiment_config(YAML::Load(test::selftest_yaml("s", 3, 2, 0)), "mem.yaml", false);
  const std::vector<RunSpec> sweep = expand_sweep(config), plan = expand_runs(config);
  ASSERT_EQ(plan.size(), sweep.size());
  for (std::size_t i = 0; i < plan.size(); ++i) EXPECT_EQ(plan[i].key, sweep[i].key);
}

/// The output of a command (stdout).
std::string output_of(const std::string& command) {
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
  pclose(pipe);
  return out;
}

// Two runs executed out of the plan: every place that lists the runs counts the same total.
TEST(PlanShaping, RunnerShardsMergeReportAndInfoCountOnePlan) {
  test::TempDir tmp;
  const fs::path config = config_file("e04_init_vs_layer_mulran");
  const std::size_t full = expand_runs(read_experiment_config(config, false)).size();
  const std::size_t quick = expand_runs(read_experiment_config(config, true)).size();
  ASSERT_EQ(quick, 3u * 4u * 4u * 3u + 2u * 4u);  // the excerpt's 4 pairs
  RunnerOptions o;
  o.results_root = tmp / "results";
  o.jobs = 2;
  o.quick = true;
  o.progress = false;
  o.max_runs = 2;
  const RunnerSummary run = run_experiment(config, o);
  EXPECT_EQ(run.total, quick);
  EXPECT_EQ(run.executed, 2u);
  const RunnerPlan resume = plan_experiment(config, o);
  EXPECT_EQ(resume.total, quick);
  EXPECT_EQ(resume.finished, 2u);
  RunnerOptions sharded = o;
  sharded.shard = Shard{0, 3};
  std::size_t in_shards = 0;
  for (const RunnerPlan& p : plan_shards(config, sharded, [&](const Shard&) { return tmp / "results"; })) {
    EXPECT_EQ(p.total, quick);
    in_shards += p.in_shard;
  }
  EXPECT_EQ(in_shards, quick);
  const MergeSummary merged = merge_results({tmp / "results"}, tmp / "merged");
  ASSERT_EQ(merged.experiments.size(), 1u);
  EXPECT_EQ(merged.experiments[0].expected, quick);
  EXPECT_EQ(merged.experiments[0].missing, quick - 2);
  write_report({tmp / "results"}, tmp / "report");
  const std::string overview = test::read_text(tmp / "report" / "overview.md");
  EXPECT_NE(overview.find("2/" + std::to_string(quick)), std::string::npos) << overview;
  const std::string info =
      output_of(std::string("'") + SEXTANT_BINARY + "' info --markdown '" + config.string() + "'");
  EXPECT_NE(info.find("| " + std::to_string(full) + " / " + std::to_string(quick) + " |"), std::string::npos)
      << info;
}

}  // namespace plan_shaping_test
}  // namespace sextant
