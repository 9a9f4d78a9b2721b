// `sextant odometry` end to end: the campus (15 scans, known ground truth), the shared uos scans
// of data/, and a small synthetic KITTI sequence folder written by the test in the benchmark's
// layout (velodyne/*.bin from campus scans, poses.txt, calib.txt, times.txt); bad arguments.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/io/kitti.hpp"
#include "sextant/core/io/trajectory_io.hpp"
#include "sextant/eval/trajectory_metrics.hpp"
#include "sextant/synth/campus.hpp"
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
CliRun run_cli(const std::string& arguments) {
  return test::run_cli(SEXTANT_CLI, arguments);
}

/// Checks the written files: TUM and KITTI trajectories with `poses` poses that agree with each
/// other (KITTI in the same frame unless `kitti_frame` is given), steps.csv with one line per
/// registration, metrics.json and provenance.json. Returns the TUM trajectory.
Trajectory expect_outputs(const fs::path& out, std::size_t poses) {
  for (const char* name :
       {"trajectory.tum", "trajectory.kitti.txt", "steps.csv", "metrics.json", "provenance.json"})
    EXPECT_TRUE(fs::exists(out / name)) << name;
  const Trajectory tum = read_tum_trajectory(out / "trajectory.tum");
  EXPECT_EQ(tum.size(), poses);
  std::ifstream steps(out / "steps.csv");
  std::size_t lines = 0;
  for (std::string line; std::getline(steps, line);) ++lines;
  EXPECT_EQ(lines, poses);  // header + poses − 1 registrations
  // Without a recovery the first registration is the one chained: its own pose columns agree.
  for (const auto& step : read_steps_csv(out / "steps.csv")) {
    if (!step.at("recovery").empty()) continue;
    for (const char* field :
         {"x_m", "y_m", "z_m", "roll_deg", "pitch_deg", "yaw_deg", "error_m", "error_deg"})
      EXPECT_EQ(step.at(std::string("first_") + field), step.at(field)) << field;
  }
  const std::string provenance = read_text(out / "provenance.json");
  for (const char* key : {"\"git\"", "\"seed\"", "\"method\"", "\"guess\"", "\"libraries\""})
    EXPECT_NE(provenance.find(key), std::string::npos) << key;
  return tum;
}

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

/// A KITTI odometry sequence folder from scans of a campus driven with ~1 m between scans (a
/// Velodyne at 10 Hz and 36 km/h), after its turn on the spot: velodyne/NNNNNN.bin, poses.txt in the
/// camera-0 frame (P_i = Tr · T0⁻¹ T_i · Tr⁻¹), calib.txt with a KITTI-like Tr, times.txt at 10 Hz.
std::vector<Eigen::Isometry3d> write_kitti_sequence(const fs::path& folder, std::size_t scans) {
  synth::CampusSettings settings;
  settings.trajectory.scans = 1400;
  const std::size_t skip = 12;  // past the turn on the spot between scans 3 and 4 of the route
  settings.trajectory.first_scans = static_cast<int>(skip + scans);
  const synth::CampusDataset campus(synth::generate_campus(settings, 3));
  Eigen::Isometry3d Tr = Eigen::Isometry3d::Identity();  // camera 0 ← Velodyne: z forward, x right
  Tr.linear() << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  Tr.translation() << -0.004, -0.076, -0.272;
  std::vector<Eigen::Isometry3d> camera;
  std::ostringstream times, calib;
  fs::create_directories(folder / "velodyne");
  for (std::size_t i = 0; i < scans; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "%06zu.bin", i);
    write_kitti_velodyne(folder / "velodyne" / name, campus.scan(skip + i));
    camera.push_back(Tr * campus.ground_truth(skip)->inverse() * *campus.ground_truth(skip + i) *
                     Tr.inverse());
    times << 0.1 * static_cast<double>(i) << "\n";
  }
  write_kitti_poses(folder / "poses.txt", camera);
  calib << "P0: 1 0 0 0 0 1 0 0 0 0 1 0\nTr:";
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) calib << " " << Tr.matrix()(r, c);
  calib << "\n";
  test::write_text(folder / "calib.txt", calib.str());
  test::write_text(folder / "times.txt", times.str());
  return camera;
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

// Issue 64, class 3: points a scan's file holds but reading it drops (here NaN) are counted per
// step in steps.csv, in the summary line and in metrics.json.
TEST(OdometryCli, DroppedPointsAreCountedPerStepAndInTheSummary) {
  TempDir tmp;
  write_kitti_sequence(tmp / "seq", 3);
  PointCloud scan = read_cloud(tmp / "seq" / "velodyne" / "000001.bin");
  const std::size_t read = scan.size() + 500;
  for (int i = 0; i < 500; ++i) scan.push_back(Eigen::Vector3f(NAN, NAN, NAN), 0.f);
  write_kitti_velodyne(tmp / "seq" / "velodyne" / "000001.bin", scan);
  const CliRun r =
      run_cli("odometry " + (tmp / "seq").string() + " --no-progress --out " + (tmp / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("dropped:  500 of "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(500 non-finite, 0 no-return), in 1 of 3 scans"), std::string::npos) << r.output;
  const auto steps = read_steps_csv(tmp / "out" / "steps.csv");
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[0].at("dropped_non_finite"), "500");  // step 0 → 1 reads scan 1
  EXPECT_EQ(steps[1].at("dropped_non_finite"), "0");
  EXPECT_EQ(steps[1].at("dropped_no_return"), "0");
  const std::string metrics = read_text(tmp / "out" / "metrics.json");
  EXPECT_EQ(json_number(metrics, "dropped_non_finite"), 500.0) << metrics;
  EXPECT_GT(json_number(metrics, "points_read"), static_cast<double>(read)) << metrics;
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

TEST(OdometryCli, BadArgumentsAreClearErrors) {
  TempDir tmp;
  const std::string out = " --out " + (tmp / "out").string();
  const std::string uos = std::string(SEXTANT_DATA_DIR) + "/uos_3dtk";
  const auto expect_error = [](const CliRun& r, const std::string& text) {
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("sextant: error:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(text), std::string::npos) << r.output;
  };
  expect_error(run_cli("odometry " + uos + " --method nosuch" + out), "unknown matcher 'nosuch'");
  expect_error(run_cli("odometry " + (tmp / "missing").string() + out), "no such dataset folder");
  expect_error(run_cli("odometry " + uos + " --guess gps" + out), "unknown guess mode 'gps'");
  expect_error(run_cli("odometry " + uos + " --map global" + out), "unknown map mode 'global'");
  expect_error(run_cli("odometry " + uos + " --loop-closure gps" + out),
               "expected proximity, descriptor or both");
  expect_error(run_cli("odometry " + uos + " --scans 5" + out), "go past the dataset's 3 scans");
  expect_error(run_cli("odometry " + uos + " --first 3" + out), "past the dataset's 3 scans");
  expect_error(run_cli("odometry " + uos + " --method icp_p2l --preset thesis" + out),
               "presets are settings");
  const CliRun negative = run_cli("odometry " + uos + " --max-acceleration -1" + out);
  EXPECT_EQ(negative.exit_code, 2) << negative.output;
  EXPECT_NE(negative.output.find("--max-acceleration"), std::string::npos) << negative.output;
  EXPECT_FALSE(fs::exists(tmp / "out"));  // nothing written before the arguments are checked
  const CliRun no_out = run_cli("odometry " + uos);
  EXPECT_NE(no_out.exit_code, 0);
  EXPECT_NE(no_out.output.find("--out"), std::string::npos) << no_out.output;
}

// Issue 64, class 5: a rerun replaces the whole file set of the earlier run, and a folder that holds
// files sextant did not write is refused, with nothing deleted.
TEST(OdometryCli, ARerunIntoTheSameFolderReplacesTheWholeSet) {
  TempDir tmp;
  const fs::path out = tmp / "out";
  const std::string command = "odometry campus --scans 3 --no-progress -q --out " + out.string();
  ASSERT_EQ(run_cli(command).exit_code, 0);
  test::write_text(out / "loop_closures.csv", "of an earlier run with --loop-closure\n");
  ASSERT_EQ(run_cli(command).exit_code, 0);
  EXPECT_FALSE(fs::exists(out / "loop_closures.csv"));
  expect_outputs(out, 3);
  for (const auto& entry : fs::directory_iterator(tmp.path()))  // no staging folder or lock left
    EXPECT_EQ(entry.path().filename(), "out");

  test::write_text(tmp / "mine" / "notes.txt", "not sextant's\n");
  const CliRun refused = run_cli("odometry campus --scans 3 --no-progress --out " + (tmp / "mine").string());
  EXPECT_EQ(refused.exit_code, 1) << refused.output;
  EXPECT_NE(refused.output.find("holds files sextant did not write (e.g. 'notes.txt')"), std::string::npos)
      << refused.output;
  EXPECT_TRUE(fs::exists(tmp / "mine" / "notes.txt"));
  EXPECT_FALSE(fs::exists(tmp / "mine" / "trajectory.tum"));
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
