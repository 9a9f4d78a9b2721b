// `sextant odometry --map-out` end to end on the built-in campus: the map file read back is the
// campus scans at the written trajectory's poses, one point per voxel; it leaves the trajectory as it
// was; inside --out it goes in with the run's files; with --loop-closure it is built from the closed
// poses; bad paths and voxels are usage errors before the run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <unordered_set>
#include <vector>

#include "odometry_cli_run.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/io/trajectory_io.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/pipeline/dataset_argument.hpp"
#include "sextant/pipeline/run_map.hpp"
#include "sextant_test/temp_dir.hpp"
#include "written_files.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;
using test::CliRun;
using test::json_number;
using test::read_text;
using test::run_cli;
using test::TempDir;

/// The maps of the campus' scans 0 … n − 1 placed by written trajectories, built here (each scan
/// generated once).
std::vector<PointCloud> campus_maps(const std::vector<fs::path>& trajectories, double voxel) {
  static const std::unique_ptr<Dataset> campus = open_builtin_campus(1);
  std::vector<Trajectory> poses;
  std::vector<RunMap> maps;
  for (const fs::path& file : trajectories) {
    poses.push_back(read_tum_trajectory(file));
    maps.emplace_back(voxel);
  }
  for (std::size_t k = 0; k < poses.front().size(); ++k) {
    const PointCloud scan = load_sequence_scan(*campus, k, 0.0);
    for (std::size_t t = 0; t < maps.size(); ++t) maps[t].add(scan, poses[t][k].pose);
  }
  std::vector<PointCloud> clouds;
  for (const RunMap& map : maps) clouds.push_back(map.cloud());
  return clouds;
}

PointCloud campus_map(const fs::path& trajectory, double voxel) {
  return campus_maps({trajectory}, voxel).front();
}

/// The share of `map`'s points whose voxel holds a point of `expected`'s (the trajectory file's 9
/// digits move a few points across a voxel's boundary).
double shared_voxels(const PointCloud& map, const PointCloud& expected, double voxel) {
  const auto key = [voxel](const Eigen::Vector3f& p) {  // 21 bits per axis: ±10 km at 1 cm
    std::uint64_t k = 0;
    for (int a = 0; a < 3; ++a)
      k = (k << 21) | static_cast<std::uint64_t>(std::lround(std::floor(p[a] / voxel)) + (1 << 20));
    return k;
  };
  std::unordered_set<std::uint64_t> occupied;
  occupied.reserve(expected.size());
  for (const Eigen::Vector3f& p : expected.points()) occupied.insert(key(p));
  std::size_t shared = 0;
  for (const Eigen::Vector3f& p : map.points()) shared += occupied.count(key(p));
  return static_cast<double>(shared) / static_cast<double>(map.size());
}

TEST(OdometryCliMap, TheMapFileIsTheScansAtTheTrajectorysPoses) {
  TempDir tmp;
  const fs::path map_file = tmp / "maps" / "campus.ply";  // outside --out, in a folder not there yet
  const CliRun r = run_cli("odometry campus --scans 12 --no-progress --out " + (tmp / "out").string() +
                           " --map-out " + map_file.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const PointCloud map = read_cloud(map_file);
  const std::string provenance = read_text(tmp / "out" / "provenance.json");
  const double voxel = json_number(provenance, "voxel_m", "map_out");
  // The default: 1/100 of the first scan's median range, rounded to 1, 2 or 5 × 10ⁿ.
  static const std::unique_ptr<Dataset> campus = open_builtin_campus(1);
  EXPECT_DOUBLE_EQ(voxel, default_map_voxel_size(load_sequence_scan(*campus, 0, 0.0))) << provenance;
  EXPECT_NE(provenance.find("1/100 of the first scan's median range"), std::string::npos) << provenance;
  EXPECT_EQ(json_number(provenance, "points", "map_out"), static_cast<double>(map.size())) << provenance;
  EXPECT_EQ(json_number(provenance, "scans", "map_out"), 12.0) << provenance;
  std::ostringstream line;
  line << "map:      " << map.size() << " points (voxel " << voxel << " m) → " << map_file.string() << "\n";
  EXPECT_NE(r.output.find(line.str()), std::string::npos) << r.output;

  const PointCloud expected = campus_map(tmp / "out" / "trajectory.tum", voxel);
  EXPECT_NEAR(static_cast<double>(map.size()), static_cast<double>(expected.size()), 0.002 * expected.size());
  EXPECT_GT(shared_voxels(map, expected, voxel), 0.998);
  // One point per voxel: fewer than the scans hold, and no two in one voxel.
  std::size_t points = 0;
  for (std::size_t k = 0; k < 12; ++k) points += campus->scan(k).size();
  EXPECT_LT(map.size(), points * 9 / 10);  // 82 % at the campus' 5 cm
  EXPECT_GT(shared_voxels(expected, map, voxel), 0.998);
}

TEST(OdometryCliMap, TheTrajectoryIsTheSameByteForByteAndAMapInsideOutGoesWithTheRun) {
  TempDir tmp;
  const std::string run = "odometry campus --scans 8 --no-progress --out ";
  const CliRun plain = run_cli(run + (tmp / "plain").string());
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  const CliRun mapped = run_cli(run + (tmp / "mapped").string() + " --map-out " +
                                (tmp / "mapped" / "map.PCD").string() + " --map-voxel 0.5");
  ASSERT_EQ(mapped.exit_code, 0) << mapped.output;
  for (const char* file : {"trajectory.tum", "trajectory.kitti.txt"})
    EXPECT_EQ(read_text(tmp / "plain" / file), read_text(tmp / "mapped" / file)) << file;
  // Inside --out: written with the run's files (swapped in together), a binary PCD.
  ASSERT_TRUE(fs::exists(tmp / "mapped" / "map.PCD"));
  EXPECT_NE(read_text(tmp / "mapped" / "map.PCD").find("DATA binary"), std::string::npos);
  const PointCloud map = read_cloud(tmp / "mapped" / "map.PCD");
  EXPECT_NE(mapped.output.find("(voxel 0.5 m)"), std::string::npos) << mapped.output;
  const PointCloud expected = campus_map(tmp / "mapped" / "trajectory.tum", 0.5);
  EXPECT_GT(shared_voxels(map, expected, 0.5), 0.998);
  const std::string provenance = read_text(tmp / "mapped" / "provenance.json");
  EXPECT_NE(provenance.find("\"voxel_from\": \"given\""), std::string::npos) << provenance;
  EXPECT_NE(read_text(tmp / "plain" / "provenance.json").find("\"map_out\": null"), std::string::npos);
  // A rerun without the map replaces the whole set: no map of the earlier run is left.
  ASSERT_EQ(run_cli(run + (tmp / "mapped").string()).exit_code, 0);
  EXPECT_FALSE(fs::exists(tmp / "mapped" / "map.PCD"));
}

// The campus' first loop comes back to its start near scan 80 (OdometryCli.LoopClosureByPlace…). Its
// chain is good to a few millimetres, which closing the loop moves: a 1 cm voxel tells the two apart.
TEST(OdometryCliMap, WithLoopClosureTheMapIsBuiltFromTheClosedPoses) {
  TempDir tmp;
  const CliRun r = run_cli("odometry campus --scans 110 --no-progress --loop-closure descriptor --out " +
                           (tmp / "out").string() + " --map-out " + (tmp / "out" / "map.ply").string() +
                           " --map-voxel 0.01");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ASSERT_NE(r.output.find("candidates closed"), std::string::npos) << r.output;
  const PointCloud map = read_cloud(tmp / "out" / "map.ply");
  const std::vector<PointCloud> expected =
      campus_maps({tmp / "out" / "trajectory.tum", tmp / "out" / "chained" / "trajectory.tum"}, 0.01);
  const double with_closed = shared_voxels(map, expected[0], 0.01);
  const double with_chained = shared_voxels(map, expected[1], 0.01);
  EXPECT_GT(with_closed, 0.999);
  EXPECT_LT(with_chained, 0.9) << "the chain's poses gave the same map";  // 0.61
  EXPECT_NE(read_text(tmp / "out" / "provenance.json").find("\"after_loop_closure\": true"),
            std::string::npos);
}

TEST(OdometryCliMap, BadPathsAndVoxelsAreUsageErrorsBeforeTheRun) {
  TempDir tmp;
  const std::string run = "odometry campus --scans 3 --no-progress --out " + (tmp / "out").string();
  const auto expect_error = [&](const std::string& options, int code, const std::string& text) {
    const CliRun r = run_cli(run + " " + options);
    EXPECT_EQ(r.exit_code, code) << options << "\n" << r.output;
    EXPECT_NE(r.output.find(text), std::string::npos) << options << "\n" << r.output;
    EXPECT_FALSE(fs::exists(tmp / "out"))
        << "nothing is written before the arguments are checked: " << options;
  };
  expect_error("--map-out " + (tmp / "map.xyz").string(), 2, "expected a .ply or .pcd file");
  expect_error("--map-out " + (tmp / "map").string(), 2, "expected a .ply or .pcd file");
  expect_error("--map-out " + (tmp / "m.ply").string() + " --map-voxel 0", 2, "--map-voxel");
  expect_error("--map-out " + (tmp / "m.ply").string() + " --map-voxel -0.1", 2, "expected a number > 0");
  expect_error("--map-out " + (tmp / "m.ply").string() + " --map-voxel nan", 2, "expected a finite number");
  expect_error("--map-out " + (tmp / "m.ply").string() + " --map-voxel big", 2, "--map-voxel");
  expect_error("--map-voxel 0.2", 2, "--map-out");  // a voxel without a map
  expect_error("--map-trusted-only", 2, "--map-out");
  fs::create_directories(tmp / "folder.ply");
  expect_error("--map-out " + (tmp / "folder.ply").string(), 1, "is a folder");
  EXPECT_EQ(run_cli("odometry campus --scans 3 --no-progress --out " + (tmp / "x.ply").string() +
                    " --map-out " + (tmp / "x.ply").string())
                .exit_code,
            1);
  EXPECT_FALSE(fs::exists(tmp / "x.ply"));
}

TEST(OdometryCliMap, TrustedOnlyCountsTheScansItLeavesOut) {
  // data/uos_3dtk: its steps are not trusted (OdometryCli.SharedUosScans): their scans are left out.
  TempDir tmp;
  const std::string uos = std::string(SEXTANT_DATA_DIR) + "/uos_3dtk";
  const CliRun all = run_cli("odometry " + uos + " --no-progress --out " + (tmp / "a").string() +
                             " --map-out " + (tmp / "a.ply").string());
  const CliRun clean = run_cli("odometry " + uos + " --no-progress --out " + (tmp / "c").string() +
                               " --map-out " + (tmp / "c.ply").string() + " --map-trusted-only");
  ASSERT_EQ(all.exit_code, 0) << all.output;
  ASSERT_EQ(clean.exit_code, 0) << clean.output;
  std::size_t untrusted = 0;
  for (const auto& step : test::read_steps_csv(tmp / "c" / "steps.csv"))
    untrusted += step.at("trust") != "ok";
  ASSERT_GE(untrusted, 1u);
  EXPECT_NE(
      clean.output.find("; " + std::to_string(untrusted) + " of 3 scans left out, placed by untrusted steps"),
      std::string::npos)
      << clean.output;
  const std::string provenance = read_text(tmp / "c" / "provenance.json");
  EXPECT_EQ(json_number(provenance, "scans_left_out", "map_out"), static_cast<double>(untrusted));
  EXPECT_EQ(json_number(provenance, "scans", "map_out"), static_cast<double>(3 - untrusted));
  EXPECT_EQ(json_number(read_text(tmp / "a" / "provenance.json"), "scans", "map_out"), 3.0);
  EXPECT_LT(read_cloud(tmp / "c.ply").size(), read_cloud(tmp / "a.ply").size());
}

}  // namespace
}  // namespace sextant
