#pragma once
// For the end-to-end tests of `sextant odometry`: running the CLI, checking the files a run writes,
// and a small synthetic KITTI sequence folder in the benchmark's layout.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/io/kitti.hpp"
#include "sextant/core/io/trajectory_io.hpp"
#include "sextant/synth/campus.hpp"
#include "sextant_test/cli_run.hpp"
#include "sextant_test/temp_dir.hpp"
#include "written_files.hpp"

namespace sextant::test {

inline CliRun run_cli(const std::string& arguments) {
  return sextant::test::run_cli(SEXTANT_CLI, arguments);
}

/// Checks the written files: TUM and KITTI trajectories with `poses` poses that agree with each
/// other (KITTI in the same frame unless `kitti_frame` is given), steps.csv with one line per
/// registration, metrics.json and provenance.json. Returns the TUM trajectory.
inline Trajectory expect_outputs(const fs::path& out, std::size_t poses) {
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

/// A KITTI odometry sequence folder from scans of a campus driven with ~1 m between scans (a
/// Velodyne at 10 Hz and 36 km/h), after its turn on the spot: velodyne/NNNNNN.bin, poses.txt in the
/// camera-0 frame (P_i = Tr · T0⁻¹ T_i · Tr⁻¹), calib.txt with a KITTI-like Tr, times.txt at 10 Hz.
inline std::vector<Eigen::Isometry3d> write_kitti_sequence(const fs::path& folder, std::size_t scans) {
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
  write_text(folder / "calib.txt", calib.str());
  write_text(folder / "times.txt", times.str());
  return camera;
}

}  // namespace sextant::test
