// Which lidar took a scan (sensor_kind.hpp): a spinning one covers the azimuth circle, a solid-state
// one a sector of it.
#include <gtest/gtest.h>

#include <cmath>

#include "sextant/core/error.hpp"
#include "sextant/core/units.hpp"
#include "sextant/matchers/sensor_kind.hpp"

namespace sextant {
namespace {

/// Points at 10 m over azimuths [from, to) degrees, 16 elevations between −15° and +15°.
PointCloud sector(double from_deg, double to_deg, int azimuths) {
  PointCloud cloud;
  for (int a = 0; a < azimuths; ++a) {
    const double az = (from_deg + (to_deg - from_deg) * a / azimuths) * kRadPerDeg;
    for (int e = 0; e < 16; ++e) {
      const double el = (-15.0 + 2.0 * e) * kRadPerDeg;
      cloud.push_back(Eigen::Vector3f(static_cast<float>(10 * std::cos(el) * std::cos(az)),
                                      static_cast<float>(10 * std::cos(el) * std::sin(az)),
                                      static_cast<float>(10 * std::sin(el))));
    }
  }
  return cloud;
}

TEST(SensorKind, AWholeCircleIsSpinningAndASectorSolidState) {
  const SensorDetection ring = detect_sensor(sector(0, 360, 1800));
  EXPECT_EQ(ring.kind, SensorKind::spinning);
  EXPECT_DOUBLE_EQ(ring.azimuth_coverage, 1.0);
  const SensorDetection avia = detect_sensor(sector(-35, 35, 400));  // a 70° field of view
  EXPECT_EQ(avia.kind, SensorKind::solid_state);
  EXPECT_NEAR(avia.azimuth_coverage, 70.0 / 360.0, 1.5 / kAzimuthSectors);
  // A spinning lidar whose rear third the platform hides, and a rotating 2D scanner's half circle.
  EXPECT_EQ(detect_sensor(sector(-120, 120, 1200)).kind, SensorKind::spinning);
  EXPECT_EQ(detect_sensor(sector(-90, 90, 900)).kind, SensorKind::spinning);
  // The widest solid-state views (120°) are solid-state; the line lies at 40 % (144°).
  EXPECT_EQ(detect_sensor(sector(-60, 60, 900)).kind, SensorKind::solid_state);
  EXPECT_EQ(detect_sensor(sector(-65, 65, 900)).kind, SensorKind::solid_state);
  EXPECT_EQ(detect_sensor(sector(-80, 80, 900)).kind, SensorKind::spinning);
}

TEST(SensorKind, AFewStrayReturnsDoNotMakeASectorSeen) {
  PointCloud cloud = sector(-35, 35, 400);
  for (int a = 0; a < 360; a += 5)  // one return every 5°, all round: reflections
    cloud.push_back(Eigen::Vector3f(static_cast<float>(50 * std::cos(a * kRadPerDeg)),
                                    static_cast<float>(50 * std::sin(a * kRadPerDeg)), 0.0f));
  EXPECT_EQ(detect_sensor(cloud).kind, SensorKind::solid_state);
}

TEST(SensorKind, AnEmptyScanTellsNothing) {
  const SensorDetection d = detect_sensor(PointCloud{});
  EXPECT_EQ(d.kind, SensorKind::spinning) << "the kind whose checks exist";
  EXPECT_DOUBLE_EQ(d.azimuth_coverage, 0.0);
}

TEST(SensorKind, DeclaredWinsAndTheMeasurementIsKept) {
  const SensorDetection d = resolve_sensor(SensorKind::spinning, sector(-35, 35, 400));
  EXPECT_EQ(d.kind, SensorKind::spinning);
  EXPECT_LT(d.azimuth_coverage, 0.25);
  EXPECT_EQ(resolve_sensor(SensorKind::automatic, sector(-35, 35, 400)).kind, SensorKind::solid_state);
}

TEST(SensorKind, NamesRoundTripAndAnUnknownOneIsNamed) {
  for (const SensorKind k : {SensorKind::automatic, SensorKind::spinning, SensorKind::solid_state})
    EXPECT_EQ(parse_enum(kSensorKindNames, to_string(k), "sensor"), k);
  try {
    parse_enum(kSensorKindNames, "mems", "--sensor");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--sensor"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("solid_state"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sextant
