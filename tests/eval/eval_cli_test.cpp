// `sextant eval` end to end: on `sextant odometry`'s own files it prints the very accuracy line
// odometry printed (TUM by time, KITTI by index); a copy of the reference moved by 5 m gives ATE 5
// without alignment and 0 with it; JSON, plots, unmatched stamps counted; bad input exits 1 or 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "sextant/core/io/trajectory_io.hpp"
#include "sextant_test/cli_run.hpp"
#include "sextant_test/temp_dir.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;

test::CliRun run_cli(const std::string& arguments) {
  return test::run_cli(SEXTANT_CLI, arguments);
}

/// The rest of the line that starts with `prefix` (empty when there is none).
std::string line_after(const std::string& text, const std::string& prefix) {
  const auto at = text.find(prefix);
  if (at == std::string::npos) return "";
  const auto start = at + prefix.size();
  return text.substr(start, text.find('\n', start) - start);
}

TEST(EvalCli, PrintsWhatOdometryPrintedForItsOwnFiles) {
  test::TempDir tmp;
  const test::CliRun odo = run_cli("odometry campus --scans 60 --no-progress --out " + (tmp / "o").string());
  ASSERT_EQ(odo.exit_code, 0) << odo.output;
  const std::string printed = line_after(odo.output, "estimate: ");
  ASSERT_NE(printed.find("ATE "), std::string::npos) << odo.output;
  for (const char* suffix : {".tum", ".kitti.txt"}) {
    const test::CliRun e = run_cli("eval " + (tmp / "o" / (std::string("groundtruth") + suffix)).string() +
                                   " " + (tmp / "o" / (std::string("trajectory") + suffix)).string());
    ASSERT_EQ(e.exit_code, 0) << e.output;
    EXPECT_NE(e.output.find("\n" + printed + "\n"), std::string::npos) << suffix << "\n"
                                                                       << printed << "\n"
                                                                       << e.output;
    EXPECT_NE(e.output.find(std::string(suffix) == ".tum" ? "60 by timestamp" : "60 by index"),
              std::string::npos)
        << e.output;
    const test::CliRun v = run_cli("eval -v " + (tmp / "o" / (std::string("groundtruth") + suffix)).string() +
                                   " " + (tmp / "o" / (std::string("trajectory") + suffix)).string());
    EXPECT_NE(v.output.find("| 100 | "), std::string::npos) << v.output;
  }
}

TEST(EvalCli, KnownOffsetJsonPlotsAndUnmatchedStamps) {
  test::TempDir tmp;
  Trajectory ref, est;
  for (int i = 0; i < 30; ++i) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(2.0 * i, 0.05 * i * i, 0.0);
    ref.push_back({10.0 + i, T});
    T.translation() += Eigen::Vector3d(3, 4, 0);
    est.push_back({10.0 + i + 0.002, T});
  }
  est.push_back({99.0, Eigen::Isometry3d::Identity()});  // no reference pose near
  write_tum_trajectory(tmp / "ref.tum", ref);
  write_tum_trajectory(tmp / "est.tum", est);
  const std::string files = (tmp / "ref.tum").string() + " " + (tmp / "est.tum").string();

  const test::CliRun none = run_cli("eval " + files + " --align none --plot " + (tmp / "plots").string());
  ASSERT_EQ(none.exit_code, 0) << none.output;
  EXPECT_NE(none.output.find("ATE 5.000 m / 0.00°"), std::string::npos) << none.output;
  EXPECT_NE(none.output.find("unmatched: 1 of the estimate, 0 of the reference"), std::string::npos)
      << none.output;
  for (const char* svg : {"trajectories.svg", "error_along_path.svg"})
    EXPECT_GT(fs::file_size(tmp / "plots" / svg), 500u) << svg;

  const test::CliRun json = run_cli("eval " + files + " --json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  EXPECT_NE(json.output.find("\"pairs\": 30"), std::string::npos) << json.output;
  EXPECT_NE(json.output.find("\"unmatched_estimate\": 1"), std::string::npos) << json.output;
  EXPECT_NE(json.output.find("\"ate_m\": {\"rms\": "), std::string::npos) << json.output;
  EXPECT_NE(json.output.find("\"kind\": \"se3\""), std::string::npos) << json.output;
  EXPECT_NE(json.output.find("\"roll_from_orientations\": false"), std::string::npos) << json.output;
  const test::CliRun quiet = run_cli("-q eval " + files);
  EXPECT_EQ(quiet.output,
            "ATE 0.000 m / 0.00°, RPE 0.000 m / 0.00° per scan, drift n/a (path shorter than 100 m)\n");
  const test::CliRun aligned = run_cli("eval " + files);
  EXPECT_NE(aligned.output.find("ATE 0.000 m"), std::string::npos) << aligned.output;

  const test::CliRun tight = run_cli("eval " + files + " --max-diff 0.001");
  EXPECT_EQ(tight.exit_code, 1) << tight.output;
  EXPECT_NE(tight.output.find("no estimate pose has a reference pose within"), std::string::npos)
      << tight.output;
}

// A trajectory is in time order whatever the order of its lines: the estimate shuffled gives the same
// ATE, RPE and drift as in order, with a note that it was sorted (issue 64: the RPE was 16× off).
TEST(EvalCli, LinesOutOfTimeOrderGiveTheSameAccuracy) {
  test::TempDir tmp;
  Trajectory ref, est;
  for (int i = 0; i < 120; ++i) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(1.5 * i, 4.0 * std::sin(0.05 * i), 0.0);
    ref.push_back({100.0 + i, T});
    T.translation() += Eigen::Vector3d(0.01 * i, -0.02 * std::cos(0.3 * i), 0.0);  // drifts, wobbles
    est.push_back({100.0 + i, T});
  }
  write_tum_trajectory(tmp / "ref.tum", ref);
  write_tum_trajectory(tmp / "est.tum", est);
  Trajectory shuffled = est;
  for (std::size_t i = 0; i + 7 < shuffled.size(); i += 7) std::swap(shuffled[i], shuffled[i + 5]);
  std::reverse(shuffled.begin() + 40, shuffled.begin() + 80);
  write_tum_trajectory(tmp / "shuffled.tum", shuffled);
  const test::CliRun ordered =
      run_cli("-q eval " + (tmp / "ref.tum").string() + " " + (tmp / "est.tum").string());
  ASSERT_EQ(ordered.exit_code, 0) << ordered.output;
  const test::CliRun mixed =
      run_cli("-q eval " + (tmp / "ref.tum").string() + " " + (tmp / "shuffled.tum").string());
  ASSERT_EQ(mixed.exit_code, 0) << mixed.output;
  EXPECT_NE(mixed.output.find("poses come after a later stamp; the trajectory is taken in time order"),
            std::string::npos)
      << mixed.output;
  const std::string accuracy = ordered.output.substr(0, ordered.output.find('\n'));
  EXPECT_NE(mixed.output.find(accuracy), std::string::npos) << ordered.output << "\n" << mixed.output;
  EXPECT_EQ(ordered.output.find("note:"), std::string::npos) << ordered.output;
}

// On a straight line the positions leave the rotation about it free: the output says the
// orientations set it (alignment_roll.hpp), in text and JSON.
TEST(EvalCli, SaysWhenTheRollAboutAStraightPathComesFromTheOrientations) {
  test::TempDir tmp;
  Trajectory ref, est;
  for (int i = 0; i < 20; ++i) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(2.0 * i, 0.0, 0.0);
    ref.push_back({double(i), T});
    T.translation().z() += 0.02 * (i % 3);  // a little vertical error; the orientations are exact
    est.push_back({double(i), T});
  }
  write_tum_trajectory(tmp / "ref.tum", ref);
  write_tum_trajectory(tmp / "est.tum", est);
  const std::string files = (tmp / "ref.tum").string() + " " + (tmp / "est.tum").string();
  const test::CliRun text = run_cli("eval " + files);
  ASSERT_EQ(text.exit_code, 0) << text.output;
  EXPECT_NE(
      text.output.find("leave the rotation about it free by more than 1°, so it comes from the orientations"),
      std::string::npos)
      << text.output;
  EXPECT_NE(text.output.find("/ 0.00°"), std::string::npos) << text.output;
  const test::CliRun json = run_cli("eval " + files + " --json");
  EXPECT_NE(json.output.find("\"roll_from_orientations\": true"), std::string::npos) << json.output;
}

// --car-slip: a straight drive along −x of the sensor whose reference jumps 0.8 m to the left on step
// 6 (a car cannot) is listed with that step and slip, in the text and the JSON; off, nothing is said.
TEST(EvalCli, ListsTheReferenceStepsACarCannotMake) {
  test::TempDir tmp;
  Trajectory ref;
  for (int i = 0; i < 12; ++i) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(-5.0 * i, i >= 7 ? 0.8 : 0.0, 0.0);
    ref.push_back({double(i), T});
  }
  write_kitti_trajectory(tmp / "ref.txt", ref);
  const std::string files = (tmp / "ref.txt").string() + " " + (tmp / "ref.txt").string();
  const test::CliRun text = run_cli("eval " + files + " --car-slip 0.5");
  ASSERT_EQ(text.exit_code, 0) << text.output;
  EXPECT_EQ(line_after(text.output, "reference: 1 step slip sideways more than 0.50 m"),
            ", which a car cannot (the car's axis 0.0° from the sensor's x): 6→7 0.80 m")
      << text.output;
  const test::CliRun json = run_cli("eval " + files + " --car-slip 0.5 --json");
  EXPECT_NE(json.output.find("\"steps\": [{\"step\": 6, \"slip_m\": 0.7999"), std::string::npos)
      << json.output;
  EXPECT_EQ(run_cli("eval " + files + " --car-slip 1").output.find("6→7"), std::string::npos);
  EXPECT_EQ(run_cli("eval " + files).output.find("slip"), std::string::npos);
}

// --ground-plane: an estimate of a 300 m straight drive that pitches up 0.0115° a step (a height drift
// and nothing else) drifts over 0.5 % in 3D and less than a tenth of that on the ground plane; the text
// and the JSON say the trajectories were projected.
TEST(EvalCli, OnTheGroundPlaneAPitchDriftLeavesNoDrift) {
  test::TempDir tmp;
  Trajectory ref, est;
  Eigen::Isometry3d climbing = Eigen::Isometry3d::Identity();
  for (int i = 0; i <= 300; ++i) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(i, 0.0, 0.0);
    ref.push_back({double(i), T});
    est.push_back({double(i), climbing});
    Eigen::Isometry3d step(Eigen::AngleAxisd(-0.0002, Eigen::Vector3d::UnitY()));  // nose up
    step.translation() = Eigen::Vector3d(1.0, 0.0, 0.0);
    climbing = climbing * step;
  }
  write_kitti_trajectory(tmp / "ref.txt", ref);
  write_kitti_trajectory(tmp / "est.txt", est);
  const std::string files = (tmp / "ref.txt").string() + " " + (tmp / "est.txt").string();
  const auto drift = [](const std::string& json) {
    const auto at = json.find("\"drift_percent\": ");
    return at == std::string::npos ? -1.0 : std::stod(json.substr(at + 17));
  };
  const test::CliRun in_3d = run_cli("eval " + files + " --json");
  ASSERT_EQ(in_3d.exit_code, 0) << in_3d.output;
  EXPECT_NE(in_3d.output.find("\"ground_plane\": false"), std::string::npos) << in_3d.output;
  const test::CliRun flat = run_cli("eval " + files + " --ground-plane --json");
  ASSERT_EQ(flat.exit_code, 0) << flat.output;
  EXPECT_NE(flat.output.find("\"ground_plane\": true"), std::string::npos) << flat.output;
  EXPECT_GT(drift(in_3d.output), 0.5) << in_3d.output;
  EXPECT_GE(drift(flat.output), 0.0) << flat.output;
  EXPECT_LT(drift(flat.output), 0.1 * drift(in_3d.output)) << flat.output;
  EXPECT_NE(run_cli("eval " + files + " --ground-plane").output.find("projected: both onto the ground plane"),
            std::string::npos);
  EXPECT_EQ(run_cli("eval " + files).output.find("projected:"), std::string::npos);
}

TEST(EvalCli, BadInputIsAClearError) {
  test::TempDir tmp;
  Trajectory a, b;
  for (int i = 0; i < 5; ++i) a.push_back({double(i), Eigen::Isometry3d::Identity()});
  b = a;
  b.pop_back();
  write_kitti_trajectory(tmp / "a.txt", a);
  write_kitti_trajectory(tmp / "b.txt", b);
  const test::CliRun lengths = run_cli("eval " + (tmp / "a.txt").string() + " " + (tmp / "b.txt").string());
  EXPECT_EQ(lengths.exit_code, 1);
  EXPECT_NE(lengths.output.find("the estimate has 4 poses and the reference 5"), std::string::npos)
      << lengths.output;
  std::ofstream(tmp / "bad.txt") << "1 2 3\n";
  const test::CliRun bad = run_cli("eval " + (tmp / "a.txt").string() + " " + (tmp / "bad.txt").string());
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.output.find("bad.txt"), std::string::npos) << bad.output;
  const test::CliRun usage =
      run_cli("eval " + (tmp / "a.txt").string() + " " + (tmp / "a.txt").string() + " --align affine");
  EXPECT_EQ(usage.exit_code, 2) << usage.output;
}

}  // namespace
}  // namespace sextant
