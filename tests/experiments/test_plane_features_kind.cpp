// The `plane_features` kind: E10 (table 4.1) with its exact values for the fixed seed, and E11's
// quick profile (extraction, association, precision/recall on the campus) — outputs and shapes.
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

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

/// Each figure's SVG exists and the summary lists them in this order.
void expect_figures_in_order(const std::filesystem::path& folder, const std::string& summary,
                             const std::vector<std::string>& ids) {
  std::size_t last = 0;
  for (const std::string& id : ids) {
    EXPECT_TRUE(std::filesystem::exists(folder / (id + ".svg"))) << id;
    const std::size_t at = summary.find("(" + id + ".svg)");
    ASSERT_NE(at, std::string::npos) << id;
    EXPECT_GE(at, last) << id << " is out of order";
    last = at;
  }
}

// Repetition 0 draws the planes from seed 1, exactly as tests/features/merging_test.cpp's seed 1
// (C_p 4.74 / 2.91 / 12.88 / 10.70 against the thesis' 5.14 / 2.38 / 44.77 / 141.74).
TEST(E10, QuickProfileGivesTheFixedSeedValuesAndTheReport) {
  TempDir tmp;
  const RunnerSummary s =
      test::run_quick(test::experiments_dir() / "e10_merging_tests.yaml", tmp / "results");
  ASSERT_EQ(s.failed, 0u);
  ASSERT_EQ(s.executed, 30u);
  const RunRow* first = nullptr;
  const auto rows = read_rows(s.folder / kRunsJsonl).rows;
  for (const auto& r : rows)
    if (r.repetition == 0) first = &r;
  ASSERT_NE(first, nullptr);
  const std::map<std::string, double> expected{
      {"case1_12_co", 2.791312242332653},  {"case1_12_ct", 0.6174567552986131},
      {"case1_12_cp", 4.7367034407798805}, {"case1_12_dc", 15.000360191734202},
      {"case1_13_co", 2.0464777137519206}, {"case1_13_ct", 0.0002631391207432443},
      {"case1_13_cp", 2.9117136097021157}, {"case1_13_dc", 25.000043075328016},
      {"case2_12_co", 2.7913125770763334}, {"case2_12_ct", 5.614419873612151},
      {"case2_12_cp", 12.877387135503701}, {"case2_12_dc", 15.84456749669636},
      {"case2_13_co", 2.0464777629661017}, {"case2_13_ct", 4.999703624949408},
      {"case2_13_cp", 10.704992021369161}, {"case2_13_dc", 25.50423966511534}};
  for (const auto& [key, value] : expected) EXPECT_NEAR(first->value(key), value, 1e-9 * (1 + value)) << key;
  EXPECT_EQ(first->value("case1_merged_planes"), 1.0);
  EXPECT_EQ(first->value("case2_merged_planes"), 2.0);
  EXPECT_EQ(first->value("case1_12_passes"), 1.0);
  EXPECT_EQ(first->value("case2_13_passes"), 0.0);

  const ReportSummary r = write_report({tmp / "results"}, tmp / "report");
  ASSERT_TRUE(r.failed.empty()) << r.failed.front();
  const auto folder = tmp / "report" / "e10_merging_tests";
  const std::string t41 = test::read_text(folder / "table_4_1.md");
  EXPECT_EQ(test::markdown_rows(t41), 4u) << t41;
  EXPECT_NE(
      t41.find("| case 1 | 1 and 2 | 2.79 | 4.28 | 0.62 | 0.19 | 4.74 | 5.14 | 22.44 | 15.00 | 15.20 |"),
      std::string::npos)
      << t41;
  EXPECT_NE(
      t41.find("| case 2 | 1 and 3 | 2.05 | 1.62 | 5.00 | 4.86 | 10.70 | 141.74 | 114.60 | 25.50 | 25.88 |"),
      std::string::npos)
      << t41;
  EXPECT_EQ(test::markdown_rows(test::read_text(folder / "merging_repetitions.md")), 4u);
  const std::string summary = test::read_text(folder / "e10_merging_tests.md");
  // Figs 4.1, 4.2 (a), 4.2 (b) in the thesis' order, then ours.
  expect_figures_in_order(
      folder, summary,
      {"merging_problem", "generated_planes_case1", "generated_planes_case2", "cp_against_dc"});
  // d_c does not separate the cases (a sanity check of the scene), C_p does: computed verdicts on the
  // 30 quick repetitions.
  EXPECT_NE(
      summary.find("d_c nearly the same in both cases (case 2 / case 1 within ±10 %), so only the other "
                   "criteria can tell them apart | holds"),
      std::string::npos)
      << summary;
  EXPECT_GT(summary.find("d_c nearly the same"), summary.find("Sanity checks")) << summary;
  EXPECT_NE(summary.find("case 2 above (no merge) | holds"), std::string::npos) << summary;
}

TEST(E11, QuickProfileWritesExtractionAssociationAndPrecisionRecall) {
  TempDir tmp;
  const RunnerSummary s =
      test::run_quick(test::experiments_dir() / "e11_extraction_association.yaml", tmp / "results");
  ASSERT_EQ(s.failed, 0u);
  ASSERT_EQ(s.executed, 5u);  // scan pairs 0 → 1 … 4 → 5
  for (const auto& r : read_rows(s.folder / kRunsJsonl).rows) {
    EXPECT_GT(r.value("landmarks"), 0.0);
    EXPECT_LE(r.value("true_positives"), r.value("landmarks"));
    EXPECT_LE(r.value("recalled_true_planes"), r.value("visible_true_planes"));
    for (const char* pose : {"none", "odometry", "truth"}) {
      const std::string p = pose;
      EXPECT_LE(r.value("assoc_" + p + "_correct"), r.value("assoc_" + p + "_true_plane"));
      EXPECT_LE(r.value("assoc_" + p + "_true_plane"), r.value("assoc_" + p + "_matches"));
      EXPECT_EQ(r.series.at("crit_" + p + "_co").size(),
                static_cast<std::size_t>(r.value("assoc_" + p + "_matches")));
    }
    if (r.point.at("scan") == "3") {
      EXPECT_NEAR(std::abs(r.value("true_yaw_deg")), 51.5, 1.0);  // the sharp turn
    }
  }
  const ReportSummary r = write_report({tmp / "results"}, tmp / "report");
  ASSERT_TRUE(r.failed.empty()) << r.failed.front();
  const auto folder = tmp / "report" / "e11_extraction_association";
  EXPECT_EQ(test::markdown_rows(test::read_text(folder / "extraction_first_scans.md")), 5u);
  EXPECT_EQ(test::markdown_rows(test::read_text(folder / "association_first_pairs.md")), 5u);
  // Table 5.10 was computed with the ground-truth motion (§5.2): the true-pose table carries the
  // thesis' values; the predicted-pose table is our extension, with no thesis column.
  const std::string truth = test::read_text(folder / "table_5_10_truth.md");
  EXPECT_GE(test::markdown_rows(truth), 4u);
  EXPECT_NE(truth.find("true (ground-truth) motion, as the thesis computed it (ours \\| thesis)"),
            std::string::npos)
      << truth;
  EXPECT_NE(truth.find("| 19.50 |"), std::string::npos) << truth;  // thesis c2 of feature 1
  const std::string predicted = test::read_text(folder / "table_5_10_odometry.md");
  EXPECT_NE(predicted.find("Our extension (not in the thesis)"), std::string::npos) << predicted;
  EXPECT_EQ(predicted.find("(thesis)"), std::string::npos) << predicted;
  EXPECT_EQ(predicted.find("19.50"), std::string::npos) << predicted;
  const std::string md = test::read_text(folder / "e11_extraction_association.md");
  EXPECT_LT(md.find("as the thesis computed it"), md.find("Our extension (not in the thesis)")) << md;
  // The turn needs a pose by the thresholds (51.5° > t_o = 20°): a sanity check, listed apart.
  EXPECT_GT(md.find("° turn cannot be dealt with"), md.find("Sanity checks")) << md;
  EXPECT_NE(md.find("decided by the thresholds"), std::string::npos) << md;
  EXPECT_EQ(test::markdown_rows(test::read_text(folder / "precision_recall.md")), 8u);
  // Figs 5.21, 5.22, 5.23, 5.24 (across the turn 3 → 4), 5.25, then ours.
  expect_figures_in_order(folder, test::read_text(folder / "e11_extraction_association.md"),
                          {"cell_segments_scan_0", "features_scan_0", "features_scan_1",
                           "correspondence_scans_3_4", "feature_map", "precision_recall_per_scan"});
  const std::string map = test::read_text(folder / "feature_map.svg");
  EXPECT_NE(map.find(">robot poses</text>"), std::string::npos);
}

TEST(PlaneFeaturesKind, RejectsAnUnknownStudyAndKeys) {
  const auto parse = [](const std::string& text) {
    const ExperimentConfig c = parse_experiment_config(YAML::Load(text), "x.yaml", false);
    run_kind_registry().create(c.kind)->validate(c);
  };
  EXPECT_THROW(parse("name: x\nkind: plane_features\nmethods: [{name: a}]\nparams: {study: nothing}\n"),
               InputError);
  EXPECT_THROW(
      parse("name: x\nkind: plane_features\nmethods: [{name: a}]\nparams: {study: merging, planes: []}\n"),
      InputError);
}

}  // namespace
}  // namespace sextant
