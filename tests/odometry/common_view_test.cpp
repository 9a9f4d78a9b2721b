// What two scans can both see (common_view.hpp): a scan's band of elevations and range from its own
// points, and each cloud cut to what the other sensor sees from the guess.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "sextant/core/rng.hpp"
#include "sextant/core/units.hpp"
#include "sextant/odometry/common_view.hpp"

namespace sextant {
namespace {

/// A point at `range` metres, `elevation_deg` above the sensor's horizon, `azimuth_deg` from x.
Eigen::Vector3f polar(double range, double elevation_deg, double azimuth_deg) {
  const double e = elevation_deg * kRadPerDeg, a = azimuth_deg * kRadPerDeg;
  return Eigen::Vector3d(range * std::cos(e) * std::cos(a), range * std::cos(e) * std::sin(a),
                         range * std::sin(e))
      .cast<float>();
}

Eigen::Isometry3d forward(double x) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation().x() = x;
  return T;
}

TEST(CommonView, AScanSeesItsBandOfElevationsWidenedByADegreeAndItsFarthestRange) {
  PointCloud scan;
  for (const double e : {-15.0, -3.0, 0.0, 7.0, 20.0})
    scan.push_back(polar(10.0 + std::fabs(e), e, 30.0 * e));
  scan.push_back(polar(50.0, 2.0, 100.0));
  scan.push_back(Eigen::Vector3f(std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f));  // left out
  const SensorView view = sensor_view(scan);
  EXPECT_NEAR(view.min_slope, std::tan(-16.0 * kRadPerDeg), 1e-6);
  EXPECT_NEAR(view.max_slope, std::tan(21.0 * kRadPerDeg), 1e-6);
  EXPECT_NEAR(view.max_range, 50.0, 1e-5);
  EXPECT_TRUE(view.sees(polar(49.0, 20.5, 0.0).cast<double>()));
  EXPECT_FALSE(view.sees(polar(49.0, 21.5, 0.0).cast<double>()));   // above the band
  EXPECT_FALSE(view.sees(polar(49.0, -16.5, 0.0).cast<double>()));  // below it
  EXPECT_FALSE(view.sees(polar(51.0, 0.0, 0.0).cast<double>()));    // beyond the range
  EXPECT_FALSE(view.sees(Eigen::Vector3d(std::nan(""), 0.0, 0.0)));
  EXPECT_FALSE(sensor_view(PointCloud()).sees(Eigen::Vector3d(1.0, 0.0, 0.0)));  // an empty scan sees nothing
}

TEST(CommonView, EachCloudKeepsWhatTheOtherSensorSeesFromTheGuess) {
  // Both sensors see elevations −15…+15° (the band's two points, 30 m to the left, seen from both);
  // the reference reaches 35 m, the input 38 m, and the input's sensor stands 10 m ahead.
  PointCloud band;
  for (const double e : {-15.0, 15.0}) band.push_back(polar(30.0, e, 90.0));
  PointCloud reference = band, input = band;
  const Eigen::Vector3f wall_top(20.0f, 0.0f, 4.0f);  // 11.3° from the reference, 21.8° from the input
  const Eigen::Vector3f behind(-35.0f, 0.0f, 0.0f);   // 35 m behind the reference, 45 m behind the input
  const Eigen::Vector3f ahead(38.0f, 0.0f, 0.0f);     // 38 m ahead of the input, 48 m ahead of the reference
  reference.push_back(wall_top);
  reference.push_back(behind);
  input.push_back(ahead);
  input.push_back(Eigen::Vector3f(5.0f, 0.0f, 0.0f));  // 15 m ahead of the reference: both see it
  std::tie(reference, input) =
      common_view(reference, sensor_view(reference), input, sensor_view(input), forward(10.0));
  ASSERT_EQ(reference.size(), 2u);  // the band's two points
  for (const Eigen::Vector3f& p : reference.points()) EXPECT_NE(p, wall_top) << "above the input's band";
  for (const Eigen::Vector3f& p : reference.points()) EXPECT_NE(p, behind) << "beyond the input's range";
  ASSERT_EQ(input.size(), 3u);
  for (const Eigen::Vector3f& p : input.points()) EXPECT_NE(p, ahead) << "beyond the reference's range";
}

// A cloud with intensities keeps each kept point's intensity, in order; one without gets none.
TEST(CommonView, KeptPointsKeepTheirIntensities) {
  PointCloud reference;
  for (const double e : {-15.0, 15.0}) reference.push_back(polar(30.0, e, 90.0));
  PointCloud input = reference;
  input.push_back(Eigen::Vector3f(5.0f, 0.0f, 0.0f));    // seen
  input.push_back(Eigen::Vector3f(200.0f, 0.0f, 0.0f));  // beyond the reference's range
  input.push_back(Eigen::Vector3f(6.0f, 1.0f, 0.0f));    // seen
  input.intensity() = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f};
  const auto [cut_reference, cut_input] = common_view(reference, sensor_view(reference), input,
                                                      sensor_view(input), Eigen::Isometry3d::Identity());
  ASSERT_EQ(cut_input.size(), 4u);
  EXPECT_EQ(cut_input.intensity(), (std::vector<float>{0.1f, 0.2f, 0.3f, 0.5f}));
  EXPECT_EQ(cut_input[3], Eigen::Vector3f(6.0f, 1.0f, 0.0f));
  EXPECT_FALSE(cut_reference.has_intensity());
}

// A planar scanner (every point at elevation 0) still sees its own plane from a guess tilted by less
// than the band's 1° margin, and nothing of it from one tilted by more.
TEST(CommonView, APlanarScannerSeesItsPlaneFromASlightlyTiltedGuess) {
  PointCloud plane;
  for (int a = 0; a < 360; a += 10) plane.push_back(polar(20.0, 0.0, a));
  plane.push_back(polar(25.0, 0.0, 45.0));  // the farthest: the 20 m points lie well inside the range
  const auto inside_range = [](const PointCloud& c) {
    std::size_t n = 0;
    for (const Eigen::Vector3f& p : c.points()) n += p.norm() < 24.0f;
    return n;
  };
  const auto tilted = [](double degrees) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(degrees * kRadPerDeg, Eigen::Vector3d::UnitY()).toRotationMatrix();
    return T;
  };
  PointCloud reference, input;
  std::tie(reference, input) = common_view(plane, sensor_view(plane), plane, sensor_view(plane), tilted(0.5));
  EXPECT_EQ(inside_range(reference), 36u);
  EXPECT_EQ(inside_range(input), 36u);
  std::tie(reference, input) = common_view(plane, sensor_view(plane), plane, sensor_view(plane), tilted(3.0));
  EXPECT_LT(inside_range(input), 20u);  // tilted out of the band: only points near the tilt's axis stay
}

// The cut (single precision, no root) keeps exactly the points SensorView::sees keeps, for bands
// closed, open below, open above and open both ways, from a turned and shifted guess.
/// 20,000 points spread over a box 120 × 120 × 60 m about the origin.
PointCloud random_box(std::uint64_t seed) {
  Rng rng(seed);
  PointCloud cloud;
  for (int i = 0; i < 20000; ++i)
    cloud.push_back(Eigen::Vector3f(static_cast<float>(rng.uniform(-60.0, 60.0)),
                                    static_cast<float>(rng.uniform(-60.0, 60.0)),
                                    static_cast<float>(rng.uniform(-30.0, 30.0))));
  return cloud;
}

/// A guess turned `angle` about a tilted axis and shifted by `shift`.
Eigen::Isometry3d turned_and_shifted(double angle, const Eigen::Vector3d& axis,
                                     const Eigen::Vector3d& shift) {
  Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();
  guess.linear() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  guess.translation() = shift;
  return guess;
}

TEST(CommonView, TheCutKeepsWhatTheViewSees) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const PointCloud cloud = random_box(7);
  const Eigen::Isometry3d guess =
      turned_and_shifted(0.3, Eigen::Vector3d(0.2, -0.1, 1.0), Eigen::Vector3d(4.0, -2.0, 0.5));
  for (const auto& [low, high] : {std::pair{-0.3, 0.4}, std::pair{-kInf, 0.2}, std::pair{-0.1, kInf},
                                  std::pair{-kInf, kInf}, std::pair{0.1, 0.5}, std::pair{-0.6, -0.2}}) {
    SCOPED_TRACE(std::to_string(low) + " … " + std::to_string(high));
    SensorView view;
    view.min_slope = low, view.max_slope = high, view.max_range = 50.0;
    std::size_t expected = 0;
    for (const Eigen::Vector3f& p : cloud.points()) expected += view.sees(guess.inverse() * p.cast<double>());
    const PointCloud reference = common_view(cloud, SensorView{}, PointCloud(), view, guess).first;
    ASSERT_EQ(reference.size(), expected);
    for (const Eigen::Vector3f& p : reference.points())
      EXPECT_TRUE(view.sees(guess.inverse() * p.cast<double>()));
    EXPECT_GT(expected, 0u);
    EXPECT_LT(expected, cloud.size());
  }
}

// A solid-state lidar sees its field of view: the circle less the largest gap between its azimuths,
// widened by a degree on each side; a spinning lidar (or a solid-state one whose gaps are all under half
// the circle) sees all of it.
TEST(CommonView, ASolidStateScanSeesItsFieldOfView) {
  PointCloud avia;  // 70° wide, centred 10° left of x, wrapping nothing
  for (int a = -25; a <= 45; ++a)
    for (const double e : {-30.0, 0.0, 30.0}) avia.push_back(polar(20.0, e, a));
  const SensorView view = sensor_view(avia, SensorKind::solid_state);
  EXPECT_NEAR(view.azimuth_centre, 10.0 * kRadPerDeg, 1e-6);
  EXPECT_NEAR(view.azimuth_half_width, 36.0 * kRadPerDeg, 1e-6);
  EXPECT_TRUE(view.sees(polar(19.0, 0.0, 45.5).cast<double>()));
  EXPECT_FALSE(view.sees(polar(19.0, 0.0, 46.5).cast<double>()));
  EXPECT_FALSE(view.sees(polar(19.0, 0.0, -26.5).cast<double>()));
  EXPECT_FALSE(view.sees(polar(19.0, 0.0, 190.0).cast<double>())) << "behind the sensor";
  EXPECT_TRUE(sensor_view(avia).sees(polar(19.0, 0.0, 190.0).cast<double>())) << "a spinning lidar's view";
  // Across ±180°: a sensor looking backwards.
  PointCloud backwards;
  for (int a = 150; a <= 210; ++a) backwards.push_back(polar(20.0, 0.0, a));
  const SensorView back = sensor_view(backwards, SensorKind::solid_state);
  EXPECT_TRUE(back.sees(polar(19.0, 0.0, 180.0).cast<double>()));
  EXPECT_TRUE(back.sees(polar(19.0, 0.0, -155.0).cast<double>()));
  EXPECT_FALSE(back.sees(polar(19.0, 0.0, 0.0).cast<double>()));
  // Gaps all under half the circle: the whole of it.
  PointCloud wide;
  for (int a = -110; a <= 110; a += 2) wide.push_back(polar(20.0, 0.0, a));
  EXPECT_GE(sensor_view(wide, SensorKind::solid_state).azimuth_half_width, kPi);
}

// The cut keeps exactly what a field of view sees, from a turned and shifted guess.
TEST(CommonView, TheCutKeepsWhatAFieldOfViewSees) {
  const PointCloud cloud = random_box(11);
  const Eigen::Isometry3d guess =
      turned_and_shifted(0.4, Eigen::Vector3d(0.1, 0.2, 1.0), Eigen::Vector3d(-3.0, 2.0, 0.2));
  for (const auto& [centre, half] : {std::pair{0.2, 0.6}, std::pair{3.0, 0.3}, std::pair{-1.5, 2.0}}) {
    SCOPED_TRACE(std::to_string(centre) + " ± " + std::to_string(half));
    SensorView view;
    view.min_slope = -0.8, view.max_slope = 0.8, view.max_range = 55.0;
    view.azimuth_centre = centre, view.azimuth_half_width = half;
    std::size_t expected = 0;
    for (const Eigen::Vector3f& p : cloud.points()) expected += view.sees(guess.inverse() * p.cast<double>());
    const PointCloud reference = common_view(cloud, SensorView{}, PointCloud(), view, guess).first;
    ASSERT_EQ(reference.size(), expected);
    EXPECT_GT(expected, 0u);
    EXPECT_LT(expected, cloud.size() / 2);
  }
}

}  // namespace
}  // namespace sextant
