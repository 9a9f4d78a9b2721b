// The `sequence` run kind: the quick profiles of E7 (chained FbML-NDT) and E9 (Table 3.3's KF)
// end to end (rows, tables, figures, TUM files), one run on the real uos scans in data/, config
// validation, and `sextant synth --scans` (a prefix of the route) vs `--stretch-route-to`.
#include <cmath>
#include <cstdlib>
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

const fs::path kSourceDir(SEXTANT_SOURCE_DIR);

void expect_tum(const fs::path& file, std::size_t poses, double first_stamp = 0) {
  ASSERT_TRUE(fs::exists(file)) << file;
  const Trajectory t = read_tum_trajectory(file);
  ASSERT_EQ(t.size(), poses) << file;
  EXPECT_EQ(t.front().stamp, first_stamp) << file;
  for (const auto& p : t) EXPECT_TRUE(p.pose.matrix().allFinite()) << file;
}

TEST(SequenceKind, E7QuickProfileChainsFbmlndtAndWritesTumFiles) {
  TempDir tmp;
  const RunnerSummary s =
      test::run_quick(test::experiments_dir() / "e07_dead_reckoning_fbmlndt.yaml", tmp / "results");
  ASSERT_EQ(s.executed, 2u);  // quick: 2 repetitions of 20 scans
  ASSERT_EQ(s.failed, 0u);
  for (const auto& row : read_rows(s.folder / kRunsJsonl).rows) {
    ASSERT_TRUE(row.ok) << row.error;
    for (const char* name : {"ground_truth", "odometry", "estimate"})
      EXPECT_EQ(row.series.at(name).size(), 12u * 20u);
    EXPECT_EQ(row.series.at("converged").size(), 19u);
    EXPECT_EQ(row.series.count("matcher"), 0u);  // no filter: the estimate is the chain
    // The chain starts at the true first pose.
    for (std::size_t k = 0; k < 12; ++k)
      EXPECT_EQ(row.series.at("estimate")[k], row.series.at("ground_truth")[k]);
    EXPECT_GT(row.value("end_xy_odometry"), 0.0);
    EXPECT_TRUE(std::isfinite(row.value("end_xy_estimate")));
  }

  const ReportSummary r = write_report({tmp / "results"}, tmp / "report");
  ASSERT_EQ(r.experiments, 1u);
  const fs::path dir = tmp / "report" / "e07_dead_reckoning_fbmlndt";
  const std::string end = test::read_text(dir / "end_point_error.md");
  EXPECT_EQ(test::markdown_rows(end), 4u) << end;  // end point and largest along the path, odometry and chain
  EXPECT_NE(end.find("60.00"), std::string::npos) << end;  // the thesis' odometry end-point error
  EXPECT_EQ(test::markdown_rows(test::read_text(dir / "trajectory_metrics.md")), 2u);
  for (const char* svg : {"trajectory.svg", "error_vs_scan.svg"}) EXPECT_TRUE(fs::exists(dir / svg)) << svg;
  for (const char* tum : {"trajectory_ground_truth.tum", "trajectory_odometry.tum", "trajectory_fbmlndt.tum"})
    expect_tum(dir / tum, 20);
  const std::string html = test::read_text(r.index_html);
  EXPECT_NE(html.find("e07_dead_reckoning_fbmlndt/trajectory_fbmlndt.tum"), std::string::npos);
}

TEST(SequenceKind, E9QuickProfileRunsTheKfWithAlarmsAndCovariance) {
  TempDir tmp;
  const RunnerSummary s = test::run_quick(test::experiments_dir() / "e09_kf_mlndt_3d.yaml", tmp / "results");
  ASSERT_EQ(s.executed, 2u);
  ASSERT_EQ(s.failed, 0u);
  for (const auto& row : read_rows(s.folder / kRunsJsonl).rows) {
    ASSERT_TRUE(row.ok) << row.error;
    EXPECT_EQ(row.series.at("matcher").size(), 12u * 20u);
    EXPECT_EQ(row.series.at("covariance_xyz").size(), 9u * 20u);
    EXPECT_EQ(row.series.at("alarm").size(), 19u);
    EXPECT_GE(row.value("alarms"), 0.0);
    EXPECT_LE(row.value("alarms"), 19.0);
    EXPECT_NEAR(row.series.at("covariance_xyz")[0], 1e-4, 1e-12);  // P0 = (0.01)² I
    // The consistency measurements: shares in [0, 1], H⁻¹'s scale against the registrations' errors
    // (H⁻¹ far too confident: > 10), and the relative fusion covering the truth at least as often as
    // table 3.3 (its P is table 3.3's plus the fused increments' covariance).
    EXPECT_GT(row.value("registration_nees_scale"), 10.0);
    for (const char* share :
         {"relative_kf_inside_95", "scaled_relative_kf_inside_95", "registration_beyond_99"}) {
      EXPECT_GE(row.value(share), 0.0) << share;
      EXPECT_LE(row.value(share), 1.0) << share;
    }
    EXPECT_GE(row.value("scaled_relative_kf_inside_95"), row.value("relative_kf_inside_95"));
  }
  const ReportSummary r = write_report({tmp / "results"}, tmp / "report");
  ASSERT_EQ(r.experiments, 1u);
  const fs::path dir = tmp / "report" / "e09_kf_mlndt_3d";
  EXPECT_EQ(test::markdown_rows(test::read_text(dir / "alarms.md")), 1u);
  EXPECT_EQ(test::markdown_rows(test::read_text(dir / "covariance.md")),
            4u);  // quick checkpoints 5, 10, 15, 20
  EXPECT_EQ(test::markdown_rows(test::read_text(dir / "trajectory_metrics.md")), 3u);
  EXPECT_EQ(test::markdown_rows(test::read_text(dir / "consistency.md")), 3u);
  // A covariance claim that does not hold says why, with the numbers measured in the run.
  const std::string md = test::read_text(dir / "e09_kf_mlndt_3d.md");
  const auto covers = md.find("The KF's covariance covers its error");
  ASSERT_NE(covers, std::string::npos);
  const std::string line = md.substr(covers, md.find('\n', covers) - covers);
  if (line.find("| does not hold |") != std::string::npos) {
    EXPECT_NE(line.find("cause: the thesis: table 3.3"), std::string::npos) << line;
    EXPECT_NE(line.find("too confident"), std::string::npos) << line;
  } else {
    EXPECT_EQ(line.find("cause:"), std::string::npos) << "a claim that holds needs no cause: " << line;
  }
  for (const char* tum : {"trajectory_ground_truth.tum", "trajectory_odometry.tum", "trajectory_mlndt.tum",
                          "trajectory_kf.tum"})
    expect_tum(dir / tum, 20);
  const std::string svg = test::read_text(dir / "trajectory.svg");
  EXPECT_NE(svg.find("σ ellipses"), std::string::npos);
}

// The real uos scans of data/uos_3dtk (Kurt3D, indoor): FbML-NDT chained over the 3 scans from the
// .pose odometry, against the .frames poses (3DTK's slam6D result). Measured: 0.09 m horizontal
// end-point error, per-step error below 0.2 m and 1.2°.
TEST(SequenceKind, ChainsFbmlndtOverTheRealUosScans) {
  TempDir tmp;
  const std::string yaml =
      "name: uos_chain\nkind: sequence\nseed: 1\n"
      "dataset: {source: folder, path: " +
      (kSourceDir / "data" / "uos_3dtk").string() +
      "}\n"
      "methods:\n  - {name: fbmlndt, matcher: fbmlndt, settings: {preset: thesis, solver: lm}, sampler: "
      "all}\n"
      "params: {scans: 3, odometry: dataset, filter: none, report: dead_reckoning}\n";
  test::write_text(tmp / "e99_uos_chain.yaml", yaml);
  const RunnerSummary s = test::run_quick(tmp / "e99_uos_chain.yaml", tmp / "results", false);
  ASSERT_EQ(s.executed, 1u);
  ASSERT_EQ(s.failed, 0u);
  const auto rows = read_rows(s.folder / kRunsJsonl).rows;
  ASSERT_EQ(rows.size(), 1u);
  ASSERT_TRUE(rows[0].ok) << rows[0].error;
  EXPECT_EQ(rows[0].series.at("estimate").size(), 36u);
  EXPECT_LT(rows[0].value("end_xy_estimate"), 0.3);
  EXPECT_LT(rows[0].value("end_3d_estimate"), 0.4);
  const ReportSummary r = write_report({tmp / "results"}, tmp / "report");
  ASSERT_EQ(r.experiments, 1u);
  expect_tum(tmp / "report" / "uos_chain" / "trajectory_fbmlndt.tum", 3);
}

TEST(SequenceKind, ValidationNamesTheKey) {
  TempDir tmp;
  const auto error_of = [&](const std::string& yaml) -> std::string {
    test::write_text(tmp / "e98_bad.yaml", yaml);
    try {
      const ExperimentConfig c = read_experiment_config(tmp / "e98_bad.yaml", false);
      run_kind_registry().create("sequence")->validate(c);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  const std::string head = "name: bad\nkind: sequence\nmethods:\n  - {name: m, matcher: mlndt}\n";
  const std::string folder =
      "dataset: {source: folder, path: " + (kSourceDir / "data" / "uos_3dtk").string() + "}\n";
  const std::string simulated = error_of(head + folder + "params: {odometry: simulated}\n");
  EXPECT_NE(simulated.find("odometry"), std::string::npos) << simulated;
  const std::string synthetic = "dataset: {source: synthetic}\n";
  const std::string scans = error_of(head + synthetic + "params:\n  scans: 1\n");
  EXPECT_NE(scans.find("line 7"), std::string::npos) << scans;
  EXPECT_NE(scans.find("'scans'"), std::string::npos) << scans;
  const std::string layout = error_of(head + synthetic + "params: {report: kalman}\n");
  EXPECT_NE(layout.find("filter: kf"), std::string::npos) << layout;
  const std::string kf =
      error_of(head + synthetic + "params: {filter: kf, report: kalman, kf: {sigma_transl: 1}}\n");
  EXPECT_NE(kf.find("sigma_transl"), std::string::npos) << kf;
  const std::string sweep = error_of(head + synthetic + "sweep:\n  pair: [0, 1]\n");
  EXPECT_NE(sweep.find("sweep"), std::string::npos) << sweep;
  EXPECT_EQ(error_of(head + synthetic), "");
}

int run_cli(const std::string& arguments) {
  const std::string command = std::string("'") + SEXTANT_BINARY + "' " + arguments + " > /dev/null 2>&1";
  return std::system(command.c_str());
}

// `--scans N` writes the first N scans of the default route (≈ 2.8 m apart, a prefix of any longer
// run); `--stretch-route-to M` spreads the whole route over M scans.
TEST(SynthCli, ScansTruncatesTheRouteAndStretchRouteToStretchesIt) {
  TempDir tmp;
  ASSERT_EQ(run_cli("synth --out '" + (tmp / "three").string() + "' --scans 3"), 0);
  ASSERT_EQ(run_cli("synth --out '" + (tmp / "five").string() + "' --scans 5"), 0);
  ASSERT_EQ(run_cli("synth --out '" + (tmp / "far").string() + "' --stretch-route-to 30 --scans 2"), 0);
  const Trajectory three = read_tum_trajectory(tmp / "three" / "ground_truth.tum");
  const Trajectory five = read_tum_trajectory(tmp / "five" / "ground_truth.tum");
  const Trajectory far = read_tum_trajectory(tmp / "far" / "ground_truth.tum");
  ASSERT_EQ(three.size(), 3u);
  ASSERT_EQ(five.size(), 5u);
  ASSERT_EQ(far.size(), 2u);
  EXPECT_TRUE(fs::exists(tmp / "three" / "scan002.3d"));
  EXPECT_FALSE(fs::exists(tmp / "three" / "scan003.3d"));
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_TRUE(three[i].pose.isApprox(five[i].pose, 1e-6)) << "scan " << i << " differs";
  const double step = (three[1].pose.translation() - three[0].pose.translation()).norm();
  EXPECT_GT(step, 1.5);
  EXPECT_LT(step, 4.0);
  const double far_step = (far[1].pose.translation() - far[0].pose.translation()).norm();
  EXPECT_GT(far_step, 5.0 * step);
  EXPECT_NE(run_cli("synth --out '" + (tmp / "bad").string() + "' --scans 500"), 0);  // past the 468 scans
  EXPECT_NE(run_cli("synth --out '" + (tmp / "bad").string() + "' --stretch-route-to 0"), 0);
  // Issue 64, class 5: three scans written over five leave a three-scan dataset, not five files
  // of which two belong to the earlier route.
  ASSERT_EQ(run_cli("synth --out '" + (tmp / "five").string() + "' --scans 3"), 0);
  EXPECT_FALSE(fs::exists(tmp / "five" / "scan003.3d"));
  EXPECT_EQ(read_tum_trajectory(tmp / "five" / "ground_truth.tum").size(), 3u);
}

}  // namespace
}  // namespace sextant
