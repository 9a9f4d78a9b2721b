// E1 (§5.1.1.1): the shipped config's quick profile end to end (output shape: tables, figures,
// success-map dimensions, iteration traces), a missing real-pair file named in the error, and the
// basin analysis helpers on known answers.
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "registration/layouts/convergence_basin_analysis.hpp"
#include "registration/scenes.hpp"
#include "sextant/core/error.hpp"
#include "sextant/experiments/report.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/experiments/runner.hpp"
#include "test_helpers.hpp"

namespace sextant {
namespace {

using test::TempDir;

const std::filesystem::path kE01Config =
    std::filesystem::path(SEXTANT_SOURCE_DIR) / "experiments" / "e01_convergence_basin.yaml";

std::size_t nonempty_lines(const std::string& text) {
  std::size_t n = 0;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) n += line.empty() ? 0 : 1;
  return n;
}

std::size_t count_fields(const std::string& line) {
  return static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1;
}

TEST(E01, QuickProfileWritesEveryTableAndFigure) {
  TempDir tmp;
  const RunnerSummary s = test::run_quick(kE01Config, tmp / "results");
  // quick: 6 methods × 4 scenes × 4 offsets × 3 yaws × 2 directions.
  ASSERT_EQ(s.executed, 6u * 4u * 4u * 3u * 2u);
  ASSERT_EQ(s.failed, 0u);

  std::size_t snapshots = 0, snapshot_reference = 0, snapshot_input = 0;
  std::set<double> scenes;
  for (const auto& row : read_rows(s.folder / kRunsJsonl).rows) {
    ASSERT_TRUE(row.ok) << row.error;
    EXPECT_EQ(row.series.at("trace_xi").size(), 6 * row.series.at("score").size());
    EXPECT_EQ(row.series.at("score").size(), static_cast<std::size_t>(row.value("iterations")));
    EXPECT_GT(row.value("cell_edge_m"), 0.0);
    scenes.insert(row.value("scene"));
    if (row.series.count("snapshot_input")) {
      ++snapshots;
      EXPECT_EQ(row.point.at("scene"), "velodyne");
      EXPECT_GT(row.series.at("snapshot_reference").size(), 300u);
      snapshot_reference = row.series.at("snapshot_reference").size() / 3;
      snapshot_input = row.series.at("snapshot_input").size() / 3;
    }
  }
  EXPECT_EQ(snapshots, 6u);  // one per method
  EXPECT_EQ(scenes.size(), 4u);

  const ReportSummary r = write_report({tmp / "results"}, tmp / "report");
  EXPECT_EQ(r.experiments, 1u);
  const auto folder = tmp / "report" / "e01_convergence_basin";
  for (const char* table :
       {"basin", "basin_ratios", "basin_per_scene", "paired_vs_baseline", "scenes", "success_map"})
    EXPECT_TRUE(std::filesystem::exists(folder / (std::string(table) + ".csv"))) << table;
  // Success map: one row per method × |yaw| value, columns method, |yaw| and the 4 offsets.
  const std::string map = test::read_text(folder / "success_map.csv");
  EXPECT_EQ(nonempty_lines(map), 1u + 6u * 3u) << map;
  EXPECT_EQ(count_fields(map.substr(0, map.find('\n'))), 2u + 4u) << map;
  const std::string basin = test::read_text(folder / "basin.md");
  for (const char* method :
       {"ndt", "ndt_magnusson", "mlndt_lm_s2", "mlndt_lm_s1", "mlndt_lm_s1_i10", "mlndt_newton_s1"})
    EXPECT_NE(basin.find("| " + std::string(method) + " |"), std::string::npos) << method << "\n" << basin;
  const std::string per_scene = test::read_text(folder / "basin_per_scene.md");
  for (const char* scene : {"campus_100", "campus_300", "velodyne", "room"})
    EXPECT_NE(per_scene.find(scene), std::string::npos) << scene;
  for (const char* figure :
       {"clouds_before", "clouds_after_mlndt_lm_s1", "clouds_after_ndt_magnusson",
        "parameters_ndt_magnusson_translation", "parameters_ndt_magnusson_rotation",
        "parameters_mlndt_lm_s1_translation", "parameters_mlndt_lm_s1_rotation", "score_ndt_magnusson",
        "newton_vs_lm_score", "newton_vs_lm_error", "success_map_ndt", "success_map_ndt_magnusson",
        "success_map_mlndt_lm_s1", "success_map_mlndt_lm_s2", "success_map_mlndt_lm_s1_i10",
        "success_map_mlndt_newton_s1", "basin_translation", "basin_yaw"})
    EXPECT_TRUE(std::filesystem::exists(folder / (std::string(figure) + ".svg"))) << figure;
  const std::string html = test::read_text(r.index_html);
  EXPECT_NE(html.find("[quick, n = 576 runs]"), std::string::npos);
  EXPECT_NE(html.find("n = 576 registrations"), std::string::npos);
  EXPECT_NE(html.find("McNemar"), std::string::npos);
  EXPECT_NE(html.find("basin is ≈ 2.5×"), std::string::npos);
  // The snapshot in 3D (figs 5.1/5.2): linked from E1's section, beside the static figures, and
  // written with the report's shared three.js; reference and input, before/after/truth states.
  const std::vector<std::string> views =
      test::view_links(test::report_section(html, "e01_convergence_basin"));
  ASSERT_EQ(views, (std::vector<std::string>{"e01_convergence_basin/clouds_3d.html"}));
  EXPECT_EQ(r.views, 1u);
  const auto page_path = tmp / "report" / views.front();
  ASSERT_TRUE(std::filesystem::is_regular_file(page_path));
  EXPECT_TRUE(std::filesystem::is_regular_file(page_path.parent_path() / ".." / "three.min.js"));
  const std::string page = test::read_text(page_path);
  EXPECT_NE(page.find("<script src=\"../three.min.js\"></script>"), std::string::npos);
  EXPECT_EQ(page.find("http://"), std::string::npos);
  EXPECT_EQ(page.find("https://"), std::string::npos);
  for (const char* state : {">before: identity guess</button>", ">after mlndt_lm_s1 (",
                            ">after ndt_magnusson (", ">ground truth</button>"})
    EXPECT_NE(page.find(state), std::string::npos) << state;
  // Every point the run stored (fewer than the viewer's cap), reference first.
  const std::size_t first = page.find("\"count\":" + std::to_string(snapshot_reference) + ",");
  const std::size_t second = page.find("\"count\":" + std::to_string(snapshot_input) + ",", first + 1);
  EXPECT_NE(first, std::string::npos);
  EXPECT_NE(second, std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(folder / "clouds_before.svg"));  // the static figures stay
}

TEST(E01, MissingPairFileIsNamed) {
  TempDir tmp;
  std::string text = test::read_text(kE01Config);
  // Absolute data paths (the copy lives elsewhere), then break the Velodyne reference.
  const std::string data = std::string(SEXTANT_DATA_DIR) + "/";
  for (std::size_t at; (at = text.find("../data/")) != std::string::npos;) text.replace(at, 8, data);
  const std::string good = "fast_gicp_251370668.pcd", bad = "fast_gicp_missing.pcd";
  text.replace(text.find(good), good.size(), bad);
  test::write_text(tmp / "e01_convergence_basin.yaml", text);
  RunnerOptions o;
  o.results_root = tmp / "results";
  o.jobs = 1;
  o.quick = true;
  o.progress = false;
  try {
    run_experiment(tmp / "e01_convergence_basin.yaml", o);
    FAIL() << "a missing pair file must stop the run";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(data + "velodyne_pair/" + bad), std::string::npos) << what;
    EXPECT_NE(what.find("velodyne"), std::string::npos) << what;
  }
}

RunRow row_with_trace(const std::vector<double>& xs) {
  RunRow row;
  const Eigen::Isometry3d truth(Eigen::Translation3d(1.0, 0, 0));
  std::vector<double> gt, init;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) {
      gt.push_back(truth.matrix()(r, c));
      init.push_back(r == c ? 1.0 : 0.0);
    }
  row.series["ground_truth"] = gt;
  row.series["initial"] = init;
  std::vector<double> xi;
  for (const double x : xs) xi.insert(xi.end(), {x, 0, 0, 0, 0, 0});
  row.series["trace_xi"] = xi;
  return row;
}

TEST(BasinAnalysis, SettleIterationAndJitter) {
  const BasinCriterion c{0.5, 2.0};
  // Iterates at x = 0 (guess), 0.2, 0.9, 1.3, 0.95, 1.0: errors 1, 0.8, 0.1, 0.3, 0.05, 0 m.
  const RunRow row = row_with_trace({0.2, 0.9, 1.3, 0.95, 1.0});
  const auto errors = iterate_errors(row);
  ASSERT_EQ(errors.size(), 6u);
  EXPECT_NEAR(errors[0].first, 1.0, 1e-12);
  EXPECT_NEAR(errors[3].first, 0.3, 1e-12);
  EXPECT_EQ(settle_iteration(errors, c), 2.0);
  // After iterate 2: steps 0.4, 0.35, 0.05 m → mean 26.67 cm.
  EXPECT_NEAR(post_settle_jitter_cm(row, 2.0), 100.0 * 0.8 / 3.0, 1e-9);
  EXPECT_TRUE(std::isnan(settle_iteration(iterate_errors(row_with_trace({0.2, 0.3})), c)));
}

// Fig. 5.5's "few iterations" is counted in ML-NDT's finest layer: the thesis' three iterations in
// each coarser layer (§3.2) come first whatever the solver does.
TEST(BasinAnalysis, IterationsInLastLayerSkipTheFixedCoarseIterations) {
  RunRow row;
  row.series["layer"] = {1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4, 4, 4};  // iterates 1–9 coarse, 10–13 finest
  EXPECT_EQ(iterations_in_last_layer(row), 4.0);
  row.series["layer"] = {2, 2, 2, 3, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4};
  EXPECT_EQ(iterations_in_last_layer(row), 9.0);  // a slow finest layer: the claim can fail
  row.series["layer"] = {0, 0, 0, 0, 0};          // single-grid NDT: every iteration counts
  EXPECT_EQ(iterations_in_last_layer(row), 5.0);
  RunRow plain;
  plain.values["iterations"] = 7;
  EXPECT_EQ(iterations_in_last_layer(plain), 7.0);  // no layer series
}

TEST(BasinAnalysis, BasinRadiusStopsAtFirstFailingValue) {
  // Offsets 0, 1, 2, 3 with 2 runs each: 2/2, 1/2, 0/2, 2/2 → at rate 0.5 the radius is 1.
  const std::vector<double> v{0, 0, 1, 1, 2, 2, 3, 3};
  const std::vector<bool> ok{true, true, true, false, false, false, true, true};
  EXPECT_EQ(basin_radius(v, ok, 0.5), 1.0);
  EXPECT_EQ(basin_radius(v, ok, 0.75), 0.0);
  EXPECT_TRUE(std::isnan(basin_radius({}, {}, 0.5)));
}

TEST(BasinAnalysis, ScoreIsNormalisedWithinEachLayer) {
  // Layer 1 falls 10 → 6, layer 2 falls 100 → 40: each runs from 1 to 0.
  const std::vector<double> y = normalise_per_layer({10, 8, 6, 100, 70, 40}, {1, 1, 1, 2, 2, 2});
  const std::vector<double> want{1, 0.5, 0, 1, 0.5, 0};
  ASSERT_EQ(y.size(), want.size());
  for (std::size_t k = 0; k < y.size(); ++k) EXPECT_NEAR(y[k], want[k], 1e-12) << k;
}

TEST(BasinAnalysis, DirectionsCoverBothSignsOfEachAxis) {
  EXPECT_EQ(direction_of(0).heading_deg, 0.0);
  EXPECT_EQ(direction_of(2).heading_deg, 180.0);
  EXPECT_EQ(direction_of(1).yaw_sign + direction_of(3).yaw_sign, 0.0);  // ±y see both yaw signs
  EXPECT_EQ(direction_of(0).yaw_sign + direction_of(2).yaw_sign, 0.0);  // ±x too
}

}  // namespace
}  // namespace sextant
