#include <gtest/gtest.h>

#include <cmath>

#include "sextant/core/geo.hpp"
#include "test_util.hpp"

namespace sextant {
namespace {

using test::expect_input_error;
using test::TempDir;
using test::write_text;

TEST(Geo, UtmOfPublishedExample) {
  // GeographicLib's GeoConvert manual: "33.3 44.4" is "38n 444140.54 3684706.36".
  const UtmCoordinate utm = to_utm({33.3, 44.4, 0.0});
  EXPECT_EQ(utm.zone, 38);
  EXPECT_TRUE(utm.northern);
  EXPECT_NEAR(utm.easting, 444140.54, 0.01);
  EXPECT_NEAR(utm.northing, 3684706.36, 0.01);
  const GeoFix back = from_utm(utm);
  EXPECT_NEAR(back.latitude, 33.3, 1e-9);
  EXPECT_NEAR(back.longitude, 44.4, 1e-9);
}

TEST(Geo, SouthernHemisphereAndInvalidFix) {
  const UtmCoordinate utm = to_utm({-33.8568, 151.2153, 0.0});  // Sydney: zone 56 south
  EXPECT_EQ(utm.zone, 56);
  EXPECT_FALSE(utm.northern);
  EXPECT_THROW(to_utm({91.0, 0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(LocalEnu({NAN, 0.0, 0.0}), std::invalid_argument);
}

TEST(Geo, EnuStepsAtTheEquator) {
  const LocalEnu enu({0.0, 0.0, 0.0});
  // One degree of latitude at the equator is 110,574 m of meridian arc; of longitude 111,320 m.
  const Eigen::Vector3d north = enu.to_enu({0.001, 0.0, 0.0});
  EXPECT_NEAR(north.y(), 110.574, 0.01);
  EXPECT_NEAR(north.x(), 0.0, 1e-6);
  const Eigen::Vector3d east = enu.to_enu({0.0, 0.001, 0.0});
  EXPECT_NEAR(east.x(), 111.319, 0.01);
  const Eigen::Vector3d up = enu.to_enu({0.0, 0.0, 12.5});
  EXPECT_NEAR(up.z(), 12.5, 1e-6);
  const GeoFix back = enu.to_geodetic(north);
  EXPECT_NEAR(back.latitude, 0.001, 1e-12);
}

TEST(Geo, EnuStepAtHannover) {
  // At 52.38° N a 0.001° latitude step is ≈ 111.26 m north (curvature of the WGS84 meridian).
  const LocalEnu enu({52.38, 9.72, 50.0});
  const Eigen::Vector3d north = enu.to_enu({52.381, 9.72, 50.0});
  EXPECT_NEAR(north.y(), 111.26, 0.05);
  EXPECT_NEAR(north.x(), 0.0, 1e-6);
}

std::string oxts_line(double lat, double lon, double alt, double roll, double pitch, double yaw) {
  std::string line = std::to_string(lat) + " " + std::to_string(lon) + " " + std::to_string(alt) + " " +
                     std::to_string(roll) + " " + std::to_string(pitch) + " " + std::to_string(yaw);
  for (int k = 6; k < 30; ++k) line += " " + std::to_string(k);
  return line + "\n";
}

TEST(Oxts, RecordsToPoses) {
  TempDir dir;
  write_text(dir / "oxts.txt",
             oxts_line(0.0, 0.0, 10.0, 0.0, 0.0, 0.0) + oxts_line(0.001, 0.0, 10.0, 0.1, -0.2, M_PI / 2));
  const auto records = read_oxts_file(dir / "oxts.txt");
  ASSERT_EQ(records.size(), 2u);
  EXPECT_DOUBLE_EQ(records[1].fields[29], 29.0);
  const Trajectory poses = oxts_to_poses(records);
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_TRUE(poses[0].pose.isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_NEAR(poses[1].pose.translation().y(), 110.574, 0.01);
  // R = Rz(yaw)·Ry(pitch)·Rx(roll) (the file holds yaw = π/2 to 6 decimals).
  const Eigen::Matrix3d expected =
      (Eigen::AngleAxisd(records[1].yaw, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  EXPECT_TRUE(poses[1].pose.linear().isApprox(expected, 1e-12));
  // The body's x axis points north for yaw = 90°.
  EXPECT_NEAR((poses[1].pose.linear() * Eigen::Vector3d::UnitX()).y(), std::cos(-0.2), 1e-6);
}

TEST(Oxts, FolderOfNumberedFiles) {
  TempDir dir;
  std::filesystem::create_directories(dir / "data");
  write_text(dir / "data" / "0000000001.txt", oxts_line(0.001, 0.0, 0.0, 0, 0, 0));
  write_text(dir / "data" / "0000000000.txt", oxts_line(0.0, 0.0, 0.0, 0, 0, 0));
  const auto records = read_oxts_folder(dir.path());
  ASSERT_EQ(records.size(), 2u);
  EXPECT_DOUBLE_EQ(records[0].fix.latitude, 0.0);
}

TEST(Oxts, BadInput) {
  TempDir dir;
  write_text(dir / "short.txt", oxts_line(0, 0, 0, 0, 0, 0) + "1 2 3\n");
  expect_input_error([&] { read_oxts_file(dir / "short.txt"); }, dir / "short.txt", "line 2", "found 3");
  write_text(dir / "nan.txt", "x" + oxts_line(0, 0, 0, 0, 0, 0));
  expect_input_error([&] { read_oxts_file(dir / "nan.txt"); }, dir / "nan.txt", "line 1", "cannot read");
  write_text(dir / "lat.txt", oxts_line(95, 0, 0, 0, 0, 0));
  expect_input_error([&] { read_oxts_file(dir / "lat.txt"); }, dir / "lat.txt", "line 1", "latitude");
}

}  // namespace
}  // namespace sextant
