// Deskewing with known answers: a scan swept here under a known constant motion, each point measured
// from the pose the sensor has at its time (by Eigen's general matrix exponential, not the closed form
// deskew uses), comes back as the instantaneous scan within float precision.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <unsupported/Eigen/MatrixFunctions>

#include "sextant/core/rng.hpp"
#include "sextant/odometry/deskew.hpp"

namespace sextant {
namespace {

constexpr double kPeriod = 0.1;  // a 10 Hz lidar's sweep [s]

/// The 4×4 matrix of the twist per second (ρ: 10 m/s forward and a little sideways and up; φ: a left
/// turn of 40°/s with some pitch and roll), and the sensor's pose after τ seconds: exp(τ·ξ^).
Eigen::Matrix4d twist_matrix() {
  const double rx = 0.05, ry = -0.08, rz = 40.0 * M_PI / 180.0;
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 1) = -rz, m(0, 2) = ry, m(1, 0) = rz, m(1, 2) = -rx, m(2, 0) = -ry, m(2, 1) = rx;
  m(0, 3) = 10.0, m(1, 3) = 0.3, m(2, 3) = -0.1;
  return m;
}

Eigen::Isometry3d pose_at(double tau) {
  return Eigen::Isometry3d(Eigen::Matrix4d((tau * twist_matrix()).exp()));
}

struct SweptScan {
  std::vector<Eigen::Vector3d> instantaneous;  ///< the points in the frame at t = 0
  PointCloud swept;                            ///< each measured from pose_at(its time)
};

/// Points up to 40 m away, taken in sweep order (or, `shuffled`, in any order) over the period.
SweptScan sweep(std::size_t n, bool shuffled, bool with_intensity) {
  Rng rng(7);
  SweptScan out;
  std::vector<float> times;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d p(rng.uniform(-40.0, 40.0), rng.uniform(-40.0, 40.0), rng.uniform(-2.0, 8.0));
    // Several points of one firing share its time, as a spinning lidar's rings do.
    const double tau = shuffled ? rng.uniform(0.0, kPeriod) : kPeriod * static_cast<double>(i / 4) / (n / 4);
    const float t = static_cast<float>(tau);
    out.instantaneous.push_back(p);
    const Eigen::Vector3f measured = (pose_at(static_cast<double>(t)).inverse() * p).cast<float>();
    if (with_intensity)
      out.swept.push_back(measured, static_cast<float>(i));
    else
      out.swept.push_back(measured);
    times.push_back(t);
  }
  out.swept.set_time(times);
  return out;
}

double worst_error(const PointCloud& cloud, const std::vector<Eigen::Vector3d>& truth) {
  double worst = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i)
    worst = std::max(worst, (cloud[i].cast<double>() - truth[i]).norm());
  return worst;
}

TEST(Deskew, ASweptScanComesBackAsTheInstantaneousOneWithinFloatPrecision) {
  for (bool shuffled : {false, true}) {
    const SweptScan scan = sweep(4000, shuffled, true);
    const SweepMotion sweep_motion{pose_at(kPeriod), kPeriod};  // what the sensor made over the sweep
    const PointCloud deskewed = deskew_scan(scan.swept, sweep_motion);
    ASSERT_EQ(deskewed.size(), scan.swept.size());
    // 40 m in float is good to 40 · 2⁻²⁴ ≈ 2.4 µm; the measured points were rounded once, the result once.
    EXPECT_LT(worst_error(deskewed, scan.instantaneous), 1e-5) << (shuffled ? "shuffled" : "in order");
    // The sweep moved the points by up to a metre and more: the test has something to undo.
    EXPECT_GT(worst_error(scan.swept, scan.instantaneous), 1.0);
    EXPECT_FALSE(deskewed.has_time()) << "a deskewed scan is one instant's";
    EXPECT_EQ(deskewed.intensity(), scan.swept.intensity());
  }
}

TEST(Deskew, TheVelocityIsTheMotionOverItsDurationWhateverTheDuration) {
  // The same velocity given as the motion over half a second: the same scan.
  const SweptScan scan = sweep(1000, true, false);
  const PointCloud deskewed = deskew_scan(scan.swept, {pose_at(0.5), 0.5});
  EXPECT_LT(worst_error(deskewed, scan.instantaneous), 1e-5);
}

TEST(Deskew, TimesBeforeTheStampAreMovedBackwards) {
  // A driver that stamps the sweep's end (Velodyne's time field: −0.1 … 0 s).
  const SweptScan scan = sweep(1000, true, false);
  PointCloud earlier = scan.swept;
  std::vector<float> times = earlier.time();
  for (std::size_t i = 0; i < times.size(); ++i) {
    times[i] -= static_cast<float>(kPeriod);
    earlier[i] = (pose_at(static_cast<double>(times[i])).inverse() * scan.instantaneous[i]).cast<float>();
  }
  earlier.set_time(times);
  EXPECT_LT(worst_error(deskew_scan(earlier, {pose_at(kPeriod), kPeriod}), scan.instantaneous), 1e-5);
}

TEST(Deskew, AScanWithoutTimesOrWithoutAMotionIsKeptAsRead) {
  const SweptScan scan = sweep(100, false, false);
  const PointCloud unknown = deskew_scan(scan.swept, SweepMotion{pose_at(kPeriod), 0.0});
  EXPECT_EQ(unknown.points(), scan.swept.points());
  EXPECT_TRUE(unknown.has_time());
  PointCloud no_time = scan.swept;
  no_time.set_time({});
  EXPECT_EQ(deskew_scan(no_time, {pose_at(kPeriod), kPeriod}).points(), no_time.points());
}

TEST(Deskew, TheSweepSpanIsTheLatestMinusTheEarliestTime) {
  PointCloud cloud(std::vector<Eigen::Vector3f>(3, Eigen::Vector3f::Ones()));
  EXPECT_EQ(sweep_span(cloud), 0.0);
  cloud.set_time({0.02f, -0.03f, 0.05f});
  EXPECT_NEAR(sweep_span(cloud), 0.08, 1e-7);
}

}  // namespace
}  // namespace sextant
