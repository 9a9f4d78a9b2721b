// E22 (ESEIF vs SEIF, an extension): the quick profile end to end — rows and series shapes, the
// ESEIF's exactly sparse Ω (pose linked to ≤ 8 landmarks after every scan with a relocation), the
// report's table, figures and claims, and its listing among the extensions on the front page.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "sextant/experiments/report.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/experiments/runner.hpp"
#include "test_helpers.hpp"

namespace sextant {
namespace {

using test::TempDir;

const std::filesystem::path kE22Config =
    std::filesystem::path(SEXTANT_SOURCE_DIR) / "experiments" / "e22_eseif_vs_seif.yaml";

TEST(E22, QuickProfileComparesNeesCostAndErrorOfSeifEseifAndEkf) {
  TempDir tmp;
  const RunnerSummary s = test::run_quick(kE22Config, tmp / "results");
  ASSERT_EQ(s.executed, 3u);  // seif, eseif, ekf × 1 repetition
  ASSERT_EQ(s.failed, 0u);
  std::map<std::string, RunRow> rows;
  for (const auto& row : read_rows(s.folder / kRunsJsonl).rows) rows[row.method] = row;
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& [method, row] : rows) {
    EXPECT_TRUE(row.ok) << row.error;
    EXPECT_EQ(row.value("scans"), 100.0) << method;
    for (const char* name : {"error_m", "nees", "nees_marginal", "step_ms", "map_size"})
      EXPECT_EQ(row.series.at(name).size(), 100u) << method << " " << name;
    EXPECT_EQ(row.value("failed_steps"), 0.0) << method;
    EXPECT_LT(row.value("max_error_m"), row.value("odometry_max_error_m")) << method;
  }
  // Paired inputs: the same odometry for every filter.
  EXPECT_EQ(rows.at("seif").series.at("odometry_error_m"), rows.at("eseif").series.at("odometry_error_m"));
  // The EKF and ESEIF report an exact covariance: the "exact marginal" NEES is the same number.
  EXPECT_EQ(rows.at("ekf").series.at("nees"), rows.at("ekf").series.at("nees_marginal"));
  EXPECT_EQ(rows.at("eseif").series.at("nees"), rows.at("eseif").series.at("nees_marginal"));
  // ESEIF relocated, and its Ω links the pose to at most Γ_a = 8 landmarks at the end.
  const RunRow& eseif = rows.at("eseif");
  EXPECT_GT(eseif.value("relocations"), 5.0);
  ASSERT_TRUE(eseif.series.count("information_1"));
  const auto& links = eseif.series.at("information_1");
  std::size_t pose_links = 0;
  for (std::size_t k = 0; k + 1 < links.size(); k += 2) pose_links += links[k] == 0.0 ? 1 : 0;
  EXPECT_LE(pose_links, 8u);
  EXPECT_EQ(static_cast<double>(pose_links), eseif.series.at("active_landmarks").back());
  EXPECT_FALSE(rows.at("ekf").series.count("active_landmarks"));

  const ReportSummary r = write_report({tmp / "results"}, tmp / "report");
  ASSERT_TRUE(r.failed.empty()) << r.failed.front();
  const auto folder = tmp / "report" / "e22_eseif_vs_seif";
  const std::string table = test::read_text(folder / "eseif_vs_seif.md");
  for (const char* method : {"| seif", "| eseif", "| ekf"}) EXPECT_NE(table.find(method), std::string::npos);
  for (const char* header :
       {"mean NEES", "NEES exact marginal", "final error m", "slope ms/landmark", "relocations"})
    EXPECT_NE(table.find(header), std::string::npos) << header << "\n" << table;
  for (const char* figure : {"nees_vs_scan", "step_time_vs_map", "error_vs_scan"})
    EXPECT_TRUE(std::filesystem::exists(folder / (std::string(figure) + ".svg"))) << figure;
  std::size_t images = 0;
  for (const auto& e : std::filesystem::directory_iterator(folder))
    if (e.path().filename().string().rfind("information_", 0) == 0) images += e.path().extension() == ".svg";
  EXPECT_EQ(images, 4u);  // seif and eseif, at 30 landmarks and at the end
  const std::string html = test::read_text(r.index_html);
  for (const char* claim : {"SEIF is overconfident", "ESEIF is consistent or conservative",
                            "ESEIF&#39;s update cost stays bounded", "final error ≈ SEIF"})
    EXPECT_NE(html.find(claim), std::string::npos) << claim;
  const auto extensions = html.find("Extensions beyond the thesis");
  ASSERT_NE(extensions, std::string::npos);
  EXPECT_GT(html.find(">E22<", extensions), extensions) << "E22 is listed among the extensions";
}

}  // namespace
}  // namespace sextant
