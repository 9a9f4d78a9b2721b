// `sextant odometry` end to end: the campus (15 scans, known ground truth), the shared uos scans
// of data/, and a small synthetic KITTI sequence folder written by the test in the benchmark's
// layout (velodyne/*.bin from campus scans, poses.txt, calib.txt, times.txt). Bad input:
// odometry_cli_input_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "odometry_cli_run.hpp"
#include "sextant/core/io/kitti.hpp"
#include "sextant/core/io/trajectory_io.hpp"
#include "sextant/eval/trajectory_metrics.hpp"
#include "sextant_test/cli_run.hpp"
#include "sextant_test/temp_dir.hpp"
#include "written_files.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;
using test::json_number;
using test::read_steps_csv;
using test::read_text;
using test::TempDir;

using test::CliRun;
using test::expect_outputs;
using test::run_cli;
using test::write_kitti_sequence;
TEST(OdometryCli, CampusFifteenScansCloseToTheTruthAndFilesReadBack) {
  TempDir tmp;
  const CliRun r = run_cli("odometry campus --scans 15 --no-progress --out " + (tmp / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("estimate: ATE"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("odometry: ATE"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("guess odometry"), std::string::npos) << r.output;
  const Trajectory tum = expect_outputs(tmp / "out", 15);
  const Trajectory kitti = read_kitti_trajectory(tmp / "out" / "trajectory.kitti.txt");
  ASSERT_EQ(kitti.size(), tum.size());
  for (std::size_t i = 0; i < tum.size(); ++i) {
    EXPECT_NEAR(tum[i].stamp, static_cast<double>(i), 1e-9);  // the campus has no clock: scan index
    EXPECT_TRUE(kitti[i].pose.isApprox(tum[i].pose, 1e-6)) << i;
  }
  const Trajectory truth = read_tum_trajectory(tmp / "out" / "groundtruth.tum");
  const AteResult ate = absolute_trajectory_error(poses_of(tum), poses_of(truth));
  EXPECT_LT(ate.translation.rms, 0.3);
  const std::string metrics = read_text(tmp / "out" / "metrics.json");
  EXPECT_NEAR(json_number(metrics, "ate_m", "estimate"), ate.translation.rms, 1e-6) << metrics;
  EXPECT_LT(json_number(metrics, "ate_m", "estimate"), json_number(metrics, "ate_m", "odometry")) << metrics;
}

TEST(OdometryCli, SharedUosScans) {
  TempDir tmp;
  const CliRun r = run_cli("odometry " + std::string(SEXTANT_DATA_DIR) + "/uos_3dtk --no-progress --out " +
                           (tmp / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("uos, 3 scans"), std::string::npos) << r.output;
  expect_outputs(tmp / "out", 3);
  const std::string metrics = read_text(tmp / "out" / "metrics.json");
  EXPECT_LT(json_number(metrics, "ate_m", "estimate"), 0.1) << metrics;  // against the .frames (slam6D)
  EXPECT_LT(json_number(metrics, "rpe_m", "estimate"), 0.1) << metrics;
  // Step 001 → 002 is low_overlap, so the dataset's odometry is chained; steps.csv keeps what the
  // scans said too (the registration, right to 3 cm).
  const auto steps = read_steps_csv(tmp / "out" / "steps.csv");
  ASSERT_EQ(steps.size(), 2u);
  const auto& step = steps[1];
  EXPECT_EQ(step.at("first_trust"), "low_overlap");
  EXPECT_EQ(step.at("recovery"), "guess");
  EXPECT_EQ(step.at("x_m"), step.at("guess_x_m")) << "the guess is chained";
  EXPECT_NE(step.at("first_x_m"), step.at("x_m"));
  EXPECT_LT(std::stod(step.at("first_error_m")), 0.1);
}

TEST(OdometryCli, SyntheticKittiSequenceFolder) {
  TempDir tmp;
  const std::vector<Eigen::Isometry3d> camera = write_kitti_sequence(tmp / "sequences" / "07", 10);
  const std::string folder = (tmp / "sequences" / "07").string();
  // KITTI has no odometry: the default guess is constant velocity; --guess odometry is refused.
  const CliRun refused = run_cli("odometry " + folder + " --guess odometry --out " + (tmp / "x").string());
  EXPECT_EQ(refused.exit_code, 1) << refused.output;
  EXPECT_NE(refused.output.find("no odometry"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("--guess constant_velocity"), std::string::npos) << refused.output;

  const CliRun r = run_cli("odometry " + folder + " --no-progress --out " + (tmp / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("kitti, 10 scans"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("guess constant_velocity"), std::string::npos) << r.output;
  const Trajectory tum = expect_outputs(tmp / "out", 10);
  EXPECT_NEAR(tum[3].stamp, 0.3, 1e-9);  // times.txt
  // The KITTI file is in the devkit's camera-0 frame: compare with poses.txt directly.
  const Trajectory kitti = read_kitti_trajectory(tmp / "out" / "trajectory.kitti.txt");
  const AteResult ate = absolute_trajectory_error(poses_of(kitti), camera);
  EXPECT_LT(ate.translation.rms, 0.2) << r.output;
  const std::string metrics = read_text(tmp / "out" / "metrics.json");
  // The ten poses lie on a line, so the alignment's turn about it is barely determined (metrics.json
  // reports a 5° ATE rotation): the files' rounding moves the ATE by a few 0.1 mm.
  EXPECT_NEAR(json_number(metrics, "ate_m", "estimate"), ate.translation.rms, 1e-3) << metrics;
  EXPECT_NE(metrics.find("\"odometry\": null"), std::string::npos) << metrics;
  EXPECT_NE(metrics.find("\"trusted_off_reference\": []"), std::string::npos) << metrics;
  EXPECT_EQ(r.output.find("check:"), std::string::npos) << r.output;
}

// A trusted step far from the reference's motion is either a wrong registration that passed the checks
// or a wrong reference (MulRan Riverside02 between keyframes 107 and 116): the run says which steps,
// on the console and in metrics.json. Here the reference jumps 3 m between scans 5 and 6. The steps are
// 0.9 m long, so a wrong one is one more than half of that off (platform.hpp), 0.45 m or 3.4°.
TEST(OdometryCli, TrustedStepsFarFromTheReferenceAreNamed) {
  TempDir tmp;
  const fs::path folder = tmp / "sequences" / "07";
  std::vector<Eigen::Isometry3d> camera = write_kitti_sequence(folder, 10);
  for (std::size_t i = 6; i < camera.size(); ++i) camera[i].translation() += Eigen::Vector3d(3.0, 0.0, 0.0);
  write_kitti_poses(folder / "poses.txt", camera);
  const CliRun r = run_cli("odometry " + folder.string() + " --no-progress --out " + (tmp / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(
      r.output.find("platform auto, typical step 0.90 m: a wrong step is one more than 0.45 m or 3.4° off"),
      std::string::npos)
      << r.output;
  EXPECT_NE(
      r.output.find("check:    1 trusted step lies more than 0.45 m or 3.4° from the reference's motion "
                    "(scans 5→6): the reference or this registration is wrong there"),
      std::string::npos)
      << r.output;
  const std::string metrics = read_text(tmp / "out" / "metrics.json");
  EXPECT_NE(metrics.find("\"trusted_off_reference\": [5]"), std::string::npos) << metrics;
}

// Issue 27 (E24): the campus' first loop comes back to its start near scan 80. Closing it with
// place recognition alone must accept only right closures and leave the trajectory better.
TEST(OdometryCli, LoopClosureByPlaceRecognitionOnTheCampus) {
  TempDir tmp;
  const CliRun r = run_cli("odometry campus --scans 110 --no-progress --loop-closure descriptor --out " +
                           (tmp / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("candidates closed (descriptor;"), std::string::npos) << r.output;
  expect_outputs(tmp / "out", 110);
  EXPECT_EQ(read_tum_trajectory(tmp / "out" / "chained" / "trajectory.tum").size(), 110u);
  std::ifstream csv(tmp / "out" / "loop_closures.csv");
  std::string line;
  std::getline(csv, line);
  ASSERT_EQ(line.substr(0, 27), "from_scan,to_scan,source,de");
  std::size_t accepted = 0;
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
    ASSERT_GE(f.size(), 14u) << line;
    EXPECT_EQ(f[2], "descriptor") << line;
    EXPECT_GE(std::stoul(f[1]), std::stoul(f[0]) + 30) << line;
    if (f[5] != "1") continue;
    ++accepted;
    EXPECT_LT(std::stod(f[12]), 0.5) << "an accepted closure is wrong: " << line;
  }
  EXPECT_GE(accepted, 3u);
  const std::string metrics = read_text(tmp / "out" / "metrics.json");
  EXPECT_EQ(json_number(metrics, "accepted", "loop_closure"), static_cast<double>(accepted)) << metrics;
  EXPECT_LT(json_number(metrics, "ate_m", "estimate"), json_number(metrics, "ate_m", "chained")) << metrics;
  // Scored against the campus' true revisits (proximity candidates: none were searched).
  EXPECT_EQ(json_number(metrics, "accepted", "descriptor"), static_cast<double>(accepted)) << metrics;
  EXPECT_EQ(json_number(metrics, "accepted_wrong", "descriptor"), 0.0) << metrics;
  EXPECT_GE(json_number(metrics, "precision", "descriptor"), 0.9) << metrics;
  EXPECT_GT(json_number(metrics, "recall", "descriptor"), 0.0) << metrics;
  EXPECT_EQ(metrics.find("\"proximity\""), std::string::npos) << metrics;
  EXPECT_NE(r.output.find("descriptor candidates"), std::string::npos) << r.output;
}

// Issue 26: -q keeps the results (the trust counts and the accuracy) and drops the rest; -v adds a
// line per registration.
TEST(OdometryCli, QuietAndVerbose) {
  TempDir tmp;
  const CliRun quiet = run_cli("odometry campus --scans 6 -q --out " + (tmp / "q").string());
  ASSERT_EQ(quiet.exit_code, 0) << quiet.output;
  EXPECT_EQ(quiet.output.find("dataset:"), std::string::npos) << quiet.output;
  EXPECT_EQ(quiet.output.find("wrote:"), std::string::npos) << quiet.output;
  EXPECT_NE(quiet.output.find("estimate: ATE"), std::string::npos) << quiet.output;
  EXPECT_NE(quiet.output.find("untrusted"), std::string::npos) << quiet.output;
  // provenance.json holds every setting the run used, the defaults included (issue 26).
  const std::string provenance = read_text(tmp / "q" / "provenance.json");
  EXPECT_NE(provenance.find("\"matcher_resolved\": {"), std::string::npos) << provenance;
  EXPECT_NE(provenance.find("\"step_control\":\"trust_region_last\""), std::string::npos) << provenance;
  EXPECT_NE(provenance.find("\"max_acceleration\": 9.81"), std::string::npos) << provenance;
  EXPECT_NE(provenance.find("\"sampler_resolved\": {\"cell_size\":1,"), std::string::npos) << provenance;
  const CliRun verbose =
      run_cli("--verbose odometry campus --scans 6 --no-progress --out " + (tmp / "v").string());
  ASSERT_EQ(verbose.exit_code, 0) << verbose.output;
  for (int k = 0; k < 5; ++k)
    EXPECT_NE(verbose.output.find("step " + std::to_string(k) + " (scans " + std::to_string(k) + "→"),
              std::string::npos)
        << verbose.output;
}

// The trust thresholds were measured with the defaults: a run outside them says so and names what
// differs; a run with the defaults (or the same settings spelled out) does not.
TEST(OdometryCli, SaysWhenTheTrustChecksRunOutsideTheirCalibration) {
  TempDir tmp;
  const std::string note = "the trust checks' thresholds were measured with the default settings";
  const CliRun plain = run_cli("odometry campus --scans 3 --no-progress --out " + (tmp / "a").string());
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_EQ(plain.output.find(note), std::string::npos) << plain.output;
  const auto with_config = [&](const std::string& name, const std::string& yaml) {
    std::ofstream(tmp / (name + ".yaml")) << yaml;
    return run_cli("odometry campus --scans 3 --no-progress --config " + (tmp / (name + ".yaml")).string() +
                   " --out " + (tmp / name).string());
  };
  const CliRun spelled = with_config("spelled", "matcher: {layers: 4}\nsampler: {cell_size: 1}\n");
  ASSERT_EQ(spelled.exit_code, 0) << spelled.output;
  EXPECT_EQ(spelled.output.find(note), std::string::npos) << spelled.output;
  const CliRun finer = with_config("finer", "matcher: {layers: 5}\nsampler: {cell_size: 0.5}\n");
  ASSERT_EQ(finer.exit_code, 0) << finer.output;
  EXPECT_NE(finer.output.find(note), std::string::npos) << finer.output;
  EXPECT_NE(finer.output.find("matcher.layers 5"), std::string::npos) << finer.output;
  EXPECT_NE(finer.output.find("sampler.cell_size 0.5"), std::string::npos) << finer.output;
  const CliRun icp =
      run_cli("odometry campus --scans 3 --no-progress --method icp_p2l --out " + (tmp / "icp").string());
  ASSERT_EQ(icp.exit_code, 0) << icp.output;
  EXPECT_NE(icp.output.find("(method icp_p2l)"), std::string::npos) << icp.output;
}

// ML-NDT registers what both sensors see by default, every other method the whole scans; each flag
// overrides the method's default, and the two exclude each other. provenance.json says which ran.
TEST(OdometryCli, CommonViewIsMlndtsDefaultAndEitherFlagOverridesIt) {
  TempDir tmp;
  const auto common_view = [&](const std::string& name, const std::string& options) {
    const CliRun r =
        run_cli("odometry campus --scans 3 --no-progress " + options + " --out " + (tmp / name).string());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return read_text(tmp / name / "provenance.json").find("\"common_view\": true") != std::string::npos;
  };
  EXPECT_TRUE(common_view("mlndt", ""));
  EXPECT_FALSE(common_view("mlndt_whole", "--whole-scans"));
  EXPECT_FALSE(common_view("icp", "--method icp_p2l"));
  EXPECT_TRUE(common_view("icp_cut", "--method icp_p2l --common-view"));
  const CliRun both =
      run_cli("odometry campus --scans 3 --common-view --whole-scans --out " + (tmp / "both").string());
  EXPECT_EQ(both.exit_code, 2) << both.output;
  EXPECT_NE(both.output.find("excludes"), std::string::npos) << both.output;
}

// --sensor and --platform: what the run assumed is printed and recorded, declared or measured; an unknown
// name is refused before anything is read.
TEST(OdometryCli, TheSensorAndPlatformAreSaidAndRecorded) {
  TempDir tmp;
  const fs::path folder = tmp / "sequences" / "07";
  write_kitti_sequence(folder, 6);
  const CliRun measured =
      run_cli("odometry " + folder.string() + " --no-progress --out " + (tmp / "a").string());
  ASSERT_EQ(measured.exit_code, 0) << measured.output;
  EXPECT_NE(measured.output.find("sensor:   spinning (measured: the first scan covers 100 % of the azimuth"),
            std::string::npos)
      << measured.output;
  const std::string auto_provenance = read_text(tmp / "a" / "provenance.json");
  EXPECT_NE(auto_provenance.find("\"declared\": \"auto\", \"used\": \"spinning\""), std::string::npos)
      << auto_provenance;
  const CliRun declared = run_cli("odometry " + folder.string() +
                                  " --sensor solid_state --platform handheld "
                                  "--no-progress --out " +
                                  (tmp / "b").string());
  ASSERT_EQ(declared.exit_code, 0) << declared.output;
  EXPECT_NE(
      declared.output.find("sensor:   solid_state (declared; the first scan covers 100 % of the azimuth "
                           "circle), no ring or horizon checks; platform handheld: a wrong step is one "
                           "more than 0.30 m or 3.0° off"),
      std::string::npos)
      << declared.output;
  const std::string provenance = read_text(tmp / "b" / "provenance.json");
  EXPECT_NE(provenance.find("\"declared\": \"solid_state\", \"used\": \"solid_state\""), std::string::npos)
      << provenance;
  EXPECT_NE(provenance.find("\"declared\": \"handheld\""), std::string::npos) << provenance;
  EXPECT_NE(provenance.find("\"tolerance_m\": 0.3"), std::string::npos) << provenance;
  const CliRun wrong =
      run_cli("odometry " + folder.string() + " --sensor mems --out " + (tmp / "c").string());
  EXPECT_NE(wrong.exit_code, 0);
  EXPECT_NE(wrong.output.find("--sensor"), std::string::npos) << wrong.output;
  EXPECT_NE(wrong.output.find("solid_state"), std::string::npos) << wrong.output;
  EXPECT_FALSE(fs::exists(tmp / "c" / "trajectory.tum"));
}

}  // namespace
}  // namespace sextant
