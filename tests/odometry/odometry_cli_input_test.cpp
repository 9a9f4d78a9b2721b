// `sextant odometry` on bad input, end to end: clear errors for bad arguments, one output folder
// holding one run, and the points a scan's file holds but reading drops counted where users look.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "odometry_cli_run.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/io/kitti.hpp"
#include "sextant_test/temp_dir.hpp"
#include "written_files.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;
using test::CliRun;
using test::expect_outputs;
using test::json_number;
using test::read_steps_csv;
using test::read_text;
using test::run_cli;
using test::TempDir;
using test::write_kitti_sequence;

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

}  // namespace
}  // namespace sextant
