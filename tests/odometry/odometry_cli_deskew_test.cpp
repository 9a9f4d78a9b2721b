// `sextant odometry` on scans whose points carry their own time (issue 63): a folder of PCD files
// written from the campus driven at 10 m/s by a lidar that sweeps in 0.1 s, with poses.txt and
// times.txt. The run says in its header whether it deskews, records it in provenance.json, and
// --no-deskew turns it off; the same scans without their times are registered as they are.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "odometry_cli_run.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/io/kitti.hpp"
#include "sextant/synth/campus.hpp"
#include "sextant_test/cli_run.hpp"
#include "sextant_test/temp_dir.hpp"
#include "written_files.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;
using test::CliRun;
using test::read_text;
using test::run_cli;
using test::TempDir;

constexpr std::size_t kScans = 8;

/// scans/NNNNNN.pcd (with a `time` field, or as .bin without), poses.txt and times.txt.
void write_sweeping_folder(const fs::path& folder, bool with_time) {
  synth::CampusSettings s;
  s.trajectory.scans = 1258;  // a scan every metre: 10 m/s at 10 Hz
  s.trajectory.first_scans = 12 + kScans;
  s.trajectory.scan_period = 0.1;
  s.sensor.yaw_steps = 120;
  s.sensor.elevation_steps = 64;
  s.sensor.sweep_period = 0.1;
  const synth::CampusDataset campus(synth::generate_campus(s, 3));
  fs::create_directories(folder / "scans");
  std::vector<Eigen::Isometry3d> poses;
  std::ofstream times(folder / "times.txt");
  for (std::size_t i = 0; i < kScans; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, with_time ? "%06zu.pcd" : "%06zu.bin", i);
    write_cloud(folder / "scans" / name, campus.scan(12 + i));  // past the turn on the spot
    poses.push_back(*campus.ground_truth(12 + i));
    times << 1000.0 + 0.1 * static_cast<double>(i) << "\n";
  }
  write_kitti_poses(folder / "poses.txt", poses);
}

TEST(OdometryCliDeskew, TheHeaderSaysWhetherScansAreDeskewedAndProvenanceRecordsIt) {
  TempDir tmp;
  write_sweeping_folder(tmp / "timed", true);
  const CliRun info = run_cli("info " + (tmp / "timed" / "scans" / "000002.pcd").string());
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_NE(info.output.find("time:        per point, 0.000000 to 0.099167 s (span 0.099167 s)"),
            std::string::npos)
      << info.output;

  const CliRun on =
      run_cli("odometry " + (tmp / "timed").string() + " --no-progress --out " + (tmp / "on").string());
  ASSERT_EQ(on.exit_code, 0) << on.output;
  EXPECT_NE(on.output.find("deskew:   constant velocity, points carry time (a sweep of 0.099 s)\n"),
            std::string::npos)
      << on.output;
  const std::string on_provenance = read_text(tmp / "on" / "provenance.json");
  EXPECT_NE(on_provenance.find("\"deskew\": {\"scheme\": \"constant_velocity\", \"scans_with_time\": 8, "
                               "\"scans_deskewed\": 8"),
            std::string::npos)
      << on_provenance;

  const CliRun off = run_cli("odometry " + (tmp / "timed").string() + " --no-deskew --no-progress --out " +
                             (tmp / "off").string());
  ASSERT_EQ(off.exit_code, 0) << off.output;
  EXPECT_NE(off.output.find("deskew:   off (--no-deskew): the points carry time (a sweep of 0.099 s) but "
                            "are registered where they were measured\n"),
            std::string::npos)
      << off.output;
  const std::string off_provenance = read_text(tmp / "off" / "provenance.json");
  EXPECT_NE(off_provenance.find("\"deskew\": {\"scheme\": \"off\", \"scans_with_time\": 8, "
                                "\"scans_deskewed\": 0, \"steps_registered_again\": 0}"),
            std::string::npos)
      << off_provenance;
  EXPECT_NE(read_text(tmp / "on" / "trajectory.tum"), read_text(tmp / "off" / "trajectory.tum"))
      << "deskewing moves the points, and the poses with them";
}

TEST(OdometryCliDeskew, ScansWithoutTimeAreRegisteredAsTheyAre) {
  TempDir tmp;
  write_sweeping_folder(tmp / "plain", false);
  const CliRun run =
      run_cli("odometry " + (tmp / "plain").string() + " --no-progress --out " + (tmp / "out").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("deskew:   off: the points carry no time\n"), std::string::npos) << run.output;
  const std::string provenance = read_text(tmp / "out" / "provenance.json");
  EXPECT_NE(provenance.find("\"scans_with_time\": 0, \"scans_deskewed\": 0, \"steps_registered_again\": 0"),
            std::string::npos)
      << provenance;
}

}  // namespace
}  // namespace sextant
