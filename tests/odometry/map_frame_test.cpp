// Odometry over scans exported in a map frame (issue 22; registration_centre.hpp): MulRan keyframes
// moved by the reference's poses into its map, and 300 m further. Each step is registered about the
// middle of its map, not about an origin hundreds of metres away, where every step said degenerate
// and chained the guess.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sextant/core/dataset.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant_test/temp_dir.hpp"
#include "shared_mulran.hpp"

namespace sextant {
namespace {

using test::kMulran;

/// Line k of a text file (k from 0).
std::string line_of(const std::filesystem::path& file, std::size_t k) {
  std::ifstream in(file);
  std::string line;
  for (std::size_t i = 0; i <= k && std::getline(in, line); ++i) {
  }
  return line;
}

/// The reference's pose of keyframe k (map ← scan), from poses.txt's 3 × 4 row.
Eigen::Isometry3d reference_pose(std::size_t k) {
  std::istringstream row(line_of(kMulran / "poses.txt", k));
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) row >> T.matrix()(r, c);
  return T;
}

TEST(MapFrameSequence, ScansFarFromTheirOriginAreRegisteredAboutTheirMap) {
  if (!std::filesystem::is_directory(kMulran)) GTEST_SKIP() << "no " << kMulran;
  test::TempDir tmp;
  const std::size_t first = 10, count = 11;
  const Eigen::Isometry3d away(Eigen::Translation3d(300, 0, 0));
  std::vector<Eigen::Isometry3d> sensor;  // where each scan's sensor stands in the exported frame
  std::string times;
  std::filesystem::create_directories(tmp.path() / "scans");
  for (std::size_t n = 0; n < count; ++n) {
    char name[32];
    std::snprintf(name, sizeof name, "%06zu.pcd", first + n);
    sensor.push_back(away * reference_pose(first + n));
    write_cloud(tmp.path() / "scans" / name, read_cloud(kMulran / "scans" / name).transformed(sensor.back()));
    times += line_of(kMulran / "times.txt", first + n) + "\n";
  }
  { std::ofstream(tmp.path() / "times.txt") << times; }
  const auto dataset = open_dataset(tmp.path());
  OdometrySettings s;
  s.guess = OdometryGuess::constant_velocity;  // the CLI's default for a folder without odometry
  const OdometryResult r = run_odometry(*dataset, s, 0, count);
  ASSERT_EQ(r.steps.size(), count - 1);
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const OdometryStep& step = r.steps[i];
    EXPECT_TRUE(step.trusted()) << "step " << i << ": " << step.quality.reason;
    // The scans already lie in one frame, so each relative pose is the identity; its error seen from
    // the sensor of scan i + 1, where a metre of lever arm turns a thousandth of a degree into
    // centimetres rather than the metres it is 300 m away.
    const Eigen::Isometry3d at_sensor = sensor[i + 1].inverse() * step.relative * sensor[i + 1];
    EXPECT_LT(translation_norm(at_sensor), 0.1) << "step " << i;
    EXPECT_LT(rotation_angle(at_sensor) * kDegPerRad, 0.5) << "step " << i;
  }
}

}  // namespace
}  // namespace sextant
