// The `simulation` kind: E8 (room, ML-NDT into the EKF, the lag) and E15 (UKF vs RSPKF Monte
// Carlo) quick profiles — rows, series, tables, figures and computed claims.
#include <cmath>

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

TEST(E8, QuickProfileTracksTheRoomLoopsAndMeasuresTheLag) {
  TempDir tmp;
  const RunnerSummary s = test::run_quick(test::experiments_dir() / "e08_ekf_mlndt_2d.yaml", tmp / "results");
  ASSERT_EQ(s.failed, 0u);
  ASSERT_EQ(s.executed, 3u);
  const auto rows = read_rows(s.folder / kRunsJsonl).rows;
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& r : rows) {
    EXPECT_GT(r.value("scans"), 20.0);
    EXPECT_EQ(r.series.at("t").size(), r.series.at("est_x").size());
    EXPECT_EQ(r.series.at("path_t").size(), r.series.at("path_x").size());
    EXPECT_GT(r.series.at("path_t").size(), r.series.at("t").size());  // the true path at every control
    EXPECT_LT(r.value("rms_estimate_m"), r.value("rms_odometry_m"));
    EXPECT_TRUE(std::isfinite(r.value("lag_s")));
    EXPECT_LE(std::abs(r.value("lag_s")), 2.0);
    // Shifting by the best lag aligns at least as well as no shift.
    EXPECT_LE(r.value("lag_cost_m"), r.value("zero_lag_cost_m") + 1e-12);
  }
  const ReportSummary rep = write_report({tmp / "results"}, tmp / "report");
  ASSERT_TRUE(rep.failed.empty()) << rep.failed.front();
  const auto folder = tmp / "report" / "e08_ekf_mlndt_2d";
  for (const char* f : {"scan_match.svg", "room_trajectory.svg", "room_errors.svg",
                        "lag_alignment_ekf_mlndt.svg", "room_errors_ekf_mlndt.md"})
    EXPECT_TRUE(std::filesystem::exists(folder / f)) << f;
  const std::string summary = test::read_text(folder / "e08_ekf_mlndt_2d.md");
  EXPECT_LT(summary.find("(scan_match.svg)"), summary.find("(room_trajectory.svg)"));  // fig. 5.17, then 5.18
  // Fig. 5.17's match (repetition 0 only): a converged ML-NDT match closer to the truth than its guess.
  for (const auto& r : rows) {
    EXPECT_EQ(r.series.count("match_reference_x"), r.repetition == 0 ? 1u : 0u);
    if (r.repetition != 0) continue;
    EXPECT_EQ(r.value("match_converged"), 1.0);
    EXPECT_EQ(r.series.at("match_guess_x").size(), r.series.at("match_matched_x").size());
    EXPECT_LT(r.value("match_error_m"), r.value("match_guess_error_m"));
  }
  EXPECT_NE(summary.find("visibly trails the true position"), std::string::npos);
  EXPECT_NE(summary.find("tracks the truth far better than dead reckoning of the same controls | holds"),
            std::string::npos)
      << summary;
}

TEST(E15, QuickProfileRunsPairedFiltersAndComparesThem) {
  TempDir tmp;
  const RunnerSummary s =
      test::run_quick(test::experiments_dir() / "e15_rspkf_vs_ukf_2d.yaml", tmp / "results");
  ASSERT_EQ(s.failed, 0u);
  ASSERT_EQ(s.executed, 12u);  // 3 filters (ukf κ = 3 − n, ukf_alpha1, rspkf) × 4 repetitions
  std::map<int, std::map<std::string, RunRow>> by_rep;
  for (const auto& r : read_rows(s.folder / kRunsJsonl).rows) by_rep[r.repetition][r.method] = r;
  ASSERT_EQ(by_rep.size(), 4u);
  for (const auto& [rep, methods] : by_rep) {
    ASSERT_EQ(methods.size(), 3u);
    const RunRow &ukf = methods.at("ukf"), &rspkf = methods.at("rspkf"), &alpha1 = methods.at("ukf_alpha1");
    EXPECT_EQ(alpha1.seed, ukf.seed);
    // Issue 25: the thesis-era UKF (κ = 3 − n) is another filter than α = 1, κ = 0, not a relabel.
    EXPECT_NE(alpha1.value("mean_position_error_m"), ukf.value("mean_position_error_m"));
    EXPECT_EQ(ukf.seed, rspkf.seed);  // paired: the same noise
    // The same simulated run: same steps and the same dead reckoning.
    EXPECT_EQ(ukf.value("steps"), 600.0);
    EXPECT_EQ(ukf.value("dead_reckoning_error_m"), rspkf.value("dead_reckoning_error_m"));
    EXPECT_EQ(ukf.value("failed_steps"), 0.0);
    EXPECT_EQ(rspkf.value("failed_steps"), 0.0);
    EXPECT_EQ(ukf.series.at("t").size(), 12u);  // every 50 steps of 600
    EXPECT_TRUE(std::isfinite(ukf.value("mean_position_error_m")));
    EXPECT_TRUE(std::isfinite(rspkf.value("mean_heading_error_deg")));
    if (rep == 0) {
      EXPECT_FALSE(rspkf.series.at("map_x").empty());
    }
  }
  const ReportSummary rep = write_report({tmp / "results"}, tmp / "report");
  ASSERT_TRUE(rep.failed.empty()) << rep.failed.front();
  const auto folder = tmp / "report" / "e15_rspkf_vs_ukf_2d";
  for (const char* f : {"average_position_error.svg", "average_heading_error.svg", "map_and_paths.svg",
                        "monte_carlo_errors.md", "monte_carlo_paired_difference.md", "sigma_points.md"})
    EXPECT_TRUE(std::filesystem::exists(folder / f)) << f;
  // Issue 25: every filter's sigma-point parameters are printed.
  const std::string sigma = test::read_text(folder / "sigma_points.md");
  EXPECT_NE(sigma.find("| ukf | ukf | unscented (Table 4.2): 2n+1 points, α = 1, β = 0, κ = 3 − n |"),
            std::string::npos)
      << sigma;
  EXPECT_NE(sigma.find("| ukf_alpha1 | ukf | unscented (Table 4.2): 2n+1 points, α = 1, β = 2, κ = 0 |"),
            std::string::npos)
      << sigma;
  EXPECT_NE(sigma.find("N_max = 3"), std::string::npos) << sigma;
  const std::string summary = test::read_text(folder / "e15_rspkf_vs_ukf_2d.md");
  EXPECT_NE(summary.find("The RSPKF's average position error norm is below the UKF's"), std::string::npos);
  EXPECT_NE(summary.find("(95 %, n = 4)"), std::string::npos) << summary;
}

// Issue 23: a Monte Carlo run whose filter maps no landmark was an "ok" row; it is a failed run.
TEST(SimulationKind, ARunThatMapsNothingIsAFailedRun) {
  TempDir tmp;
  test::write_text(tmp / "blind.yaml",
                   "name: blind\nkind: simulation\nseed: 1\nrepetitions: 1\n"
                   "methods: [{name: ukf, filter: ukf}, {name: r, filter: rspkf}]\n"
                   "params: {model: range_bearing, landmarks: 5, side: 50, baseline: ukf, proposed: r,\n"
                   "  sim: {max_range: 0.01, sigma_range: 0.001, max_steps: 50}}\n");
  RunnerOptions o;
  o.results_root = tmp / "results";
  o.jobs = 1;
  o.progress = false;
  const RunnerSummary s = run_experiment(tmp / "blind.yaml", o);
  EXPECT_EQ(s.failed, 2u);
  for (const auto& r : read_rows(s.folder / kRunsJsonl).rows) {
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("mapped no landmark (of 5 landmarks)"), std::string::npos) << r.error;
  }
}

TEST(SimulationKind, RejectsAnUnknownModelAndBadKeys) {
  const auto parse = [](const std::string& text) {
    const ExperimentConfig c = parse_experiment_config(YAML::Load(text), "x.yaml", false);
    run_kind_registry().create(c.kind)->validate(c);
  };
  EXPECT_THROW(parse("name: x\nkind: simulation\nmethods: [{name: a}]\nparams: {model: nothing}\n"),
               InputError);
  EXPECT_THROW(parse("name: x\nkind: simulation\nmethods: [{name: a, matcher: mlndt}]\n"
                     "params: {model: room_2d, room: {beam: 3}}\n"),
               InputError);
  EXPECT_THROW(parse("name: x\nkind: simulation\nmethods: [{name: ukf, filter: ukf}]\n"
                     "params: {model: range_bearing, baseline: ukf, proposed: rspkf}\n"),
               InputError);  // no method named rspkf
  EXPECT_NO_THROW(
      parse("name: x\nkind: simulation\nmethods: [{name: ukf, filter: ukf}, {name: r, filter: rspkf}]\n"
            "params: {model: range_bearing, baseline: ukf, proposed: r}\n"));
}

}  // namespace
}  // namespace sextant
