// The `registration` run kind end to end on a tiny synthetic campus: runner → rows → report, and
// config validation (unknown matcher → file, line, key).
#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/experiments/experiment_config.hpp"
#include "sextant/experiments/report.hpp"
#include "sextant/experiments/run_kind.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/experiments/runner.hpp"
#include "test_helpers.hpp"

namespace sextant {
namespace {

using test::TempDir;

// Three consecutive pairs of the default campus (only scans 0–3 are generated); ML-NDT (LM)
// from the odometry guess. Measured errors: 3.6, 3.5 and 7.1 cm, below 0.5°.
const char* const kTinyRegistration = R"(name: reg_tiny
kind: registration
seed: 3
dataset:
  source: synthetic
  seed: 1
methods:
  - {name: mlndt, matcher: mlndt, settings: {solver: lm}, sampler: gbs}
sweep:
  pair: {from: 0, to: 2}
params:
  pairs: consecutive
  guess: odometry
  report: accuracy
  proposed: mlndt
reference:
  odometry: {table: "5.1", mean: [77.52, null, 16.96, null, 0.50, null]}
  methods:
    mlndt: {table: "5.3", success_percent: 98, iterations: 12.77}
)";

TEST(RegistrationKind, TinyExperimentRunsEndToEnd) {
  TempDir tmp;
  test::write_text(tmp / "e99_reg_tiny.yaml", kTinyRegistration);
  RunnerOptions o;
  o.results_root = tmp / "results";
  o.jobs = 2;
  o.progress = false;
  const RunnerSummary s = run_experiment(tmp / "e99_reg_tiny.yaml", o);
  ASSERT_EQ(s.executed, 3u);
  ASSERT_EQ(s.failed, 0u);

  const auto rows = read_rows(s.folder / kRunsJsonl).rows;
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& row : rows) {
    EXPECT_TRUE(row.ok) << row.error;
    EXPECT_LT(row.value("translation_cm"), 10.0) << "pair " << row.point.at("pair");
    EXPECT_LT(row.value("rotation_deg"), 1.0) << "pair " << row.point.at("pair");
    EXPECT_EQ(row.value("success"), 1.0);
    EXPECT_GT(row.value("iterations"), 0.0);
    EXPECT_GT(row.value("matched_percent"), 0.0);
    EXPECT_GT(row.value("kept_fraction"), 0.0);
    EXPECT_LE(row.value("kept_fraction"), 1.0);
    EXPECT_FALSE(row.series.at("score").empty());
    EXPECT_EQ(row.series.at("estimate").size(), 12u);
    EXPECT_EQ(row.series.at("odometry").size(), 12u);
  }

  const ReportSummary r = write_report({tmp / "results"}, tmp / "report");
  EXPECT_EQ(r.experiments, 1u);
  const auto folder = tmp / "report" / "reg_tiny";
  const std::string t51 = test::read_text(folder / "table_5_1.md");
  const std::string t53 = test::read_text(folder / "table_5_3.md");
  const std::string t54 = test::read_text(folder / "table_5_4.md");
  for (const std::string* t : {&t51, &t53}) {
    for (const char* header : {"tx", "ty", "tz", "α", "β", "γ", "ours", "thesis"})
      EXPECT_NE(t->find(header), std::string::npos) << header << "\n" << *t;
  }
  EXPECT_NE(t51.find("77.52"), std::string::npos) << t51;
  for (const char* header : {"success %", "time s", "iterations", "matched %", "kept %"})
    EXPECT_NE(t54.find(header), std::string::npos) << header << "\n" << t54;
  EXPECT_NE(t54.find("mlndt | 100.0 | 98.0"), std::string::npos) << t54;
  EXPECT_TRUE(std::filesystem::exists(folder / "error_vs_scan.svg"));
}

TEST(RegistrationKind, UnknownMatcherIsRejectedWithFileLineAndKey) {
  TempDir tmp;
  std::string text = kTinyRegistration;
  const std::string from = "matcher: mlndt";
  text.replace(text.find(from), from.size(), "matcher: mlndtt");
  const auto file = tmp / "bad.yaml";
  test::write_text(file, text);
  const ExperimentConfig c = read_experiment_config(file, false);
  try {
    run_kind_registry().create(c.kind)->validate(c);
    FAIL() << "an unknown matcher must be rejected";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.file(), file.string());
    EXPECT_NE(what.find("line 8"), std::string::npos) << what;
    EXPECT_NE(what.find("'matcher'"), std::string::npos) << what;
    EXPECT_NE(what.find("mlndtt"), std::string::npos) << what;
  }
}

TEST(RegistrationKind, SweepAxesMustFitThePairSource) {
  TempDir tmp;
  std::string text = kTinyRegistration;
  text.replace(text.find("  pair: {from: 0, to: 2}"), 24, "  pair: {from: 0, to: 2}\n  yaw: [0, 5]");
  const auto file = tmp / "bad.yaml";
  test::write_text(file, text);
  const ExperimentConfig c = read_experiment_config(file, false);
  EXPECT_THROW(run_kind_registry().create(c.kind)->validate(c), InputError);
}

}  // namespace
}  // namespace sextant
