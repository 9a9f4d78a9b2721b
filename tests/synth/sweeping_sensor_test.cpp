// The campus' scanner sweeping while it moves (SensorSettings::sweep_period): each point is taken at
// its own time along the sweep from the pose the platform then has, and carries that time. Known
// answers: every point lies on the surface it hit when placed by the pose at its time (and not by the
// scan's pose, for a fast platform), its time is its ray's fraction of the sweep, and a platform at
// rest sweeps the instantaneous scan.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "sextant/core/pose.hpp"
#include "sextant/core/se3.hpp"
#include "sextant/synth/campus.hpp"
#include "small_campus.hpp"

namespace sextant::synth {
namespace {

/// The campus route driven at 10 m/s (a scan every metre, 10 Hz), its scans swept over `sweep` s.
CampusSettings fast(double sweep, const std::string& pattern = "spinning") {
  CampusSettings s = test::small_campus(1258);
  s.trajectory.first_scans = 90;
  s.trajectory.scan_period = 0.1;
  s.sensor.sweep_period = sweep;
  s.sensor.pattern = pattern;
  return s;
}

TEST(SweepingSensor, EveryPointLiesOnItsSurfaceFromThePoseAtItsTime) {
  for (const char* pattern : {"spinning", "rosette"}) {
    const CampusSettings s = fast(0.1, pattern);
    const Campus c = generate_campus(s, 3);
    for (const std::size_t i : {10u, 80u, 89u}) {  // straight, the first corner, the last scan
      const SimulatedScan scan = c.scan(i);
      ASSERT_TRUE(scan.cloud.has_time());
      const Eigen::Isometry3d& next = i + 1 < c.size() ? c.ground_truth[i + 1] : c.pose_after_last;
      const Eigen::Isometry3d step = relative(c.ground_truth[i], next);
      std::size_t off_from_the_stamp = 0;
      for (std::size_t k = 0; k < scan.cloud.size(); ++k) {
        const double t = scan.cloud.time()[k];
        const Eigen::Isometry3d at_time = c.ground_truth[i] * interpolate_motion(step, t / 0.1);
        const Eigen::Vector3d p = at_time * scan.cloud[k].cast<double>();
        EXPECT_LE(c.world->distance_to(scan.primitive[k], p), 6 * s.sensor.range_noise + 1e-4)
            << pattern << " scan " << i << " point " << k;
        const Eigen::Vector3d q = c.ground_truth[i] * scan.cloud[k].cast<double>();
        if (c.world->distance_to(scan.primitive[k], q) > 0.1) ++off_from_the_stamp;
      }
      EXPECT_GT(off_from_the_stamp, scan.cloud.size() / 8)
          << pattern << " scan " << i << ": the sweep moved them";
    }
  }
}

TEST(SweepingSensor, APointsTimeIsItsRaysFractionOfTheSweep) {
  const CampusSettings s = fast(0.08);
  const SimulatedScan scan = generate_campus(s, 3).scan(20);
  std::set<float> times(scan.cloud.time().begin(), scan.cloud.time().end());
  // A spinning scanner's rays come column by column: one time per yaw step, k / yaw_steps of 0.08 s.
  EXPECT_GT(times.size(), static_cast<std::size_t>(s.sensor.yaw_steps) * 9 / 10);
  EXPECT_LE(times.size(), static_cast<std::size_t>(s.sensor.yaw_steps));
  for (float t : times) {
    const double column = t / 0.08 * s.sensor.yaw_steps;
    EXPECT_NEAR(column, std::round(column), 1e-4) << t;
    EXPECT_GE(t, 0.0f);
    EXPECT_LT(t, 0.08f);
  }
  // Time runs with the azimuth: the first column looks forward (x), a quarter of the turn later left (y).
  for (std::size_t k = 0; k < scan.cloud.size(); ++k) {
    const double azimuth = std::atan2(scan.cloud[k].y(), scan.cloud[k].x());
    const double fraction = scan.cloud.time()[k] / 0.08;
    EXPECT_NEAR(wrap_angle(azimuth - 2 * M_PI * fraction), 0.0, 1e-4) << k;
  }
}

TEST(SweepingSensor, APlatformAtRestSweepsTheInstantaneousScan) {
  EXPECT_FALSE(generate_campus(fast(0.0), 3).scan(0).cloud.has_time());
  CampusSettings s = fast(0.1);
  s.trajectory.first_scans = 0;
  s.trajectory.scans = 1;  // a route of one pose: the platform stands still
  const Campus still = generate_campus(s, 3);
  ASSERT_TRUE(still.pose_after_last.isApprox(still.ground_truth[0]));
  const SimulatedScan swept = still.scan(0);
  const SimulatedScan cast_at_once = [&] {
    Campus c = still;
    c.settings.sensor.sweep_period = 0.0;
    return c.scan(0);
  }();
  ASSERT_TRUE(swept.cloud.has_time());
  EXPECT_EQ(swept.cloud.points(), cast_at_once.cloud.points());
}

TEST(SweepingSensor, TheSweepMayNotOutlastTheScanPeriod) {
  CampusSettings s = fast(0.2);
  std::string why;
  EXPECT_FALSE(s.valid(&why));
  EXPECT_NE(why.find("sweep_period"), std::string::npos) << why;
  s.sensor.sweep_period = -0.1;
  EXPECT_FALSE(s.valid(&why));
  EXPECT_NE(why.find("sensor.sweep_period"), std::string::npos) << why;
}

}  // namespace
}  // namespace sextant::synth
