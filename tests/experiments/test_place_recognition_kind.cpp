// The `place_recognition` run kind (E24): the quick profile end to end — each candidate source at
// no extra drift and at the inflated one, scored against the campus' true revisits — and config
// validation.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "sextant/core/error.hpp"
#include "sextant/experiments/experiment_config.hpp"
#include "sextant/experiments/report.hpp"
#include "sextant/experiments/run_kind.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/experiments/runner.hpp"
#include "sextant_test/temp_dir.hpp"
#include "test_helpers.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

TEST(PlaceRecognitionKind, E24QuickProfileScoresEachSourceAgainstTheTrueRevisits) {
  TempDir tmp;
  const RunnerSummary s =
      test::run_quick(test::experiments_dir() / "e24_place_recognition.yaml", tmp / "results");
  ASSERT_EQ(s.executed, 6u);  // 3 sources × 2 drifts, one repetition
  ASSERT_EQ(s.failed, 0u);
  for (const auto& row : read_rows(s.folder / kRunsJsonl).rows) {
    ASSERT_TRUE(row.ok) << row.error;
    const bool drifted = row.point.at("drift_yaw_deg_per_scan") != "0.0";
    EXPECT_EQ(row.value("accepted_wrong"), 0.0) << row.method;  // every accepted closure is a true revisit
    if (row.method == "descriptor") {
      EXPECT_GT(row.value("accepted"), 0.0);  // place recognition finds revisits at any drift
      EXPECT_EQ(row.value("precision"), 1.0);
    }
    if (!drifted) {
      EXPECT_GT(row.value("accepted"), 0.0) << row.method;
      EXPECT_LT(row.value("closed_ate_m"), 0.5 * row.value("chained_ate_m")) << row.method;
    } else {
      EXPECT_GT(row.value("chained_ate_m"), 2.0) << row.method;  // the drift is inflated
      if (row.method == "proximity") {
        EXPECT_EQ(row.value("accepted"), 0.0);
      }
    }
  }
  const ReportSummary r = write_report({tmp / "results"}, tmp / "report");
  ASSERT_TRUE(r.failed.empty()) << r.failed.front();
  EXPECT_EQ(r.claims, 3u);
  std::ifstream table(tmp / "report" / "e24_place_recognition" / "detection.md");
  std::string text((std::istreambuf_iterator<char>(table)), std::istreambuf_iterator<char>());
  for (const char* source : {"| proximity |", "| descriptor |", "| both |"})
    EXPECT_NE(text.find(source), std::string::npos) << source << "\n" << text;
}

TEST(PlaceRecognitionKind, ConfigErrorsNameTheKey) {
  const auto kind_ptr = run_kind_registry().create("place_recognition");
  const RunKind& kind = *kind_ptr;
  const auto config = [](const std::string& methods, const std::string& rest) {
    return parse_experiment_config(
        YAML::Load("name: e99\nkind: place_recognition\ntitle: t\nthesis: t\ndataset: {source: synthetic}\n"
                   "methods: " +
                   methods + "\n" + rest),
        "e99.yaml", false);
  };
  const std::string ok_sweep = "sweep: {drift_yaw_deg_per_scan: [0, 0.3]}\n";
  EXPECT_NO_THROW(kind.validate(config("[{name: a, candidates: both}]", ok_sweep)));
  EXPECT_THROW(kind.validate(config("[{name: a, candidates: nearby}]", ok_sweep)), InputError);
  EXPECT_THROW(kind.validate(config("[{name: a}]", ok_sweep)), InputError);
  EXPECT_THROW(kind.validate(config("[{name: a, candidates: both}]", "")), InputError);
  EXPECT_THROW(kind.validate(config("[{name: a, candidates: both}]", ok_sweep + "params: {scans: 1}\n")),
               InputError);
}

}  // namespace
}  // namespace sextant
