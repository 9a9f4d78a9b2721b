// The synthetic solid-state lidar and hand-held platform (issue 62): a rosette over a fixed field of
// view that draws another part of itself at every scan, and a sensor that sways and looks around.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"
#include "sextant/synth/campus.hpp"
#include "sextant/synth/route.hpp"

namespace sextant::synth {
namespace {

CampusSettings rosette_walk(int scans, int first) {
  CampusSettings s;
  s.trajectory.scans = scans;
  s.trajectory.first_scans = first;
  s.trajectory.platform = "handheld";
  s.sensor.pattern = "rosette";
  return s;
}

TEST(SolidStateSensor, TheRosetteFillsItsFieldOfViewAndNothingElse) {
  const Campus campus = generate_campus(rosette_walk(468, 4), 1);
  const SimulatedScan scan = campus.scan(1);
  EXPECT_EQ(scan.stats.rays, 6000u);
  EXPECT_GT(scan.cloud.size(), 3000u);
  double min_az = 1e9, max_az = -1e9, min_el = 1e9, max_el = -1e9;
  for (const Eigen::Vector3f& p : scan.cloud.points()) {
    const double az = std::atan2(p.y(), p.x()) * kDegPerRad;
    const double el = std::atan2(p.z(), std::hypot(p.x(), p.y())) * kDegPerRad;
    min_az = std::min(min_az, az), max_az = std::max(max_az, az);
    min_el = std::min(min_el, el), max_el = std::max(max_el, el);
  }
  EXPECT_GE(min_az, -35.2 - 1e-3);
  EXPECT_LE(max_az, 35.2 + 1e-3);
  EXPECT_LT(min_az, -30.0) << "the rosette reaches the edge of its view";
  EXPECT_GT(max_az, 30.0);
  EXPECT_GE(min_el, -38.6 - 1e-3);
  EXPECT_LE(max_el, 38.6 + 1e-3);
  EXPECT_GT(max_el, 25.0);
}

TEST(SolidStateSensor, EveryScanDrawsAnotherPartOfTheRosette) {
  CampusSettings s = rosette_walk(468, 3);
  s.trajectory.platform = "car";
  const Campus campus = generate_campus(s, 1);
  const SimulatedScan a = campus.scan(0), b = campus.scan(0), c = campus.scan(1);
  ASSERT_EQ(a.cloud.size(), b.cloud.size()) << "deterministic";
  for (std::size_t i = 0; i < a.cloud.size(); ++i) ASSERT_EQ(a.cloud[i], b.cloud[i]);
  // The same world seen from nearly the same place: hardly any direction repeats.
  std::set<std::pair<int, int>> directions;
  const auto key = [](const Eigen::Vector3f& p) {
    return std::pair<int, int>(
        static_cast<int>(std::lround(std::atan2(p.y(), p.x()) * 1e4)),
        static_cast<int>(std::lround(std::atan2(p.z(), std::hypot(p.x(), p.y())) * 1e4)));
  };
  for (const Eigen::Vector3f& p : a.cloud.points()) directions.insert(key(p));
  std::size_t repeated = 0;
  for (const Eigen::Vector3f& p : c.cloud.points()) repeated += directions.count(key(p));
  EXPECT_LT(repeated, c.cloud.size() / 100);
}

TEST(HandheldPlatform, TheSensorLooksAroundAndSwaysAboutTheWayItGoes) {
  TrajectorySettings t;
  EXPECT_TRUE(handheld_sway(t, 5).isIdentity()) << "a car faces the way it goes";
  t.platform = "handheld";
  double fastest = 0.0, most_tilt = 0.0;
  for (std::size_t i = 1; i < 200; ++i) {
    const Eigen::Matrix3d turn = handheld_sway(t, i - 1).transpose() * handheld_sway(t, i);
    fastest = std::max(fastest, Eigen::AngleAxisd(turn).angle() * kDegPerRad);
    const Eigen::Vector3d up = handheld_sway(t, i) * Eigen::Vector3d::UnitZ();
    most_tilt = std::max(most_tilt, std::acos(std::clamp(up.z(), -1.0, 1.0)) * kDegPerRad);
  }
  EXPECT_GT(fastest, 9.0) << "up to 2π · 40° / 23 ≈ 11° between scans";
  EXPECT_LT(fastest, 13.0);
  EXPECT_GT(most_tilt, 2.5);
  EXPECT_LT(most_tilt, 4.5) << "roll and pitch of at most 3° each";
  // In the campus the sway turns the ground truth, not the route.
  CampusSettings car = rosette_walk(468, 6), walk = rosette_walk(468, 6);
  car.trajectory.platform = "car";
  const Campus a = generate_campus(car, 2), b = generate_campus(walk, 2);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR((a.ground_truth[i].translation() - b.ground_truth[i].translation()).norm(), 0.0, 1e-12);
    EXPECT_TRUE((a.ground_truth[i].linear() * handheld_sway(walk.trajectory, i))
                    .isApprox(b.ground_truth[i].linear(), 1e-12));
  }
}

TEST(SolidStateSensor, UnknownPatternsAndPlatformsAreNamed) {
  CampusSettings s;
  std::string why;
  s.sensor.pattern = "mems";
  EXPECT_FALSE(s.valid(&why));
  EXPECT_NE(why.find("pattern"), std::string::npos) << why;
  s.sensor.pattern = "rosette";
  s.trajectory.platform = "drone";
  EXPECT_FALSE(s.valid(&why));
  EXPECT_NE(why.find("platform"), std::string::npos) << why;
}

}  // namespace
}  // namespace sextant::synth
