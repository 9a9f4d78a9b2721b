// Odometry with known answers on a solid-state lidar carried on foot (issue 62): the synthetic campus
// seen by a rosette over 70° × 77° (a Livox Avia's view), carried at walking pace (0.3 m per scan)
// while the sensor looks around (up to 11° between scans), sways (3°) and turns 10° at once between
// scans 3 and 4. Its ground truth is exact.
#include <gtest/gtest.h>

#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/synth/campus.hpp"

namespace sextant {
namespace {

synth::CampusDataset walk(int scans) {
  synth::CampusSettings s;
  s.trajectory.scans = 4200;  // the route at 0.3 m per scan
  s.trajectory.first_scans = scans;
  s.trajectory.platform = "handheld";
  s.trajectory.sensor_height = 1.5;
  s.trajectory.scan_period = 0.5;
  s.trajectory.sharp_turn_deg = 10.0;
  s.sensor.pattern = "rosette";
  s.sensor.body_length = s.sensor.body_width = 0.0;  // no vehicle below the sensor
  return synth::CampusDataset(synth::generate_campus(s, 1));
}

TEST(SyntheticWalk, TrustedStepsAreRightAndMostAreTrusted) {
  const synth::CampusDataset dataset = walk(60);
  OdometrySettings s;
  s.guess = OdometryGuess::constant_velocity;  // no odometer on a person
  const OdometryResult r = run_odometry(dataset, s, 0, 60);
  EXPECT_EQ(r.sensor.kind, SensorKind::solid_state);
  ASSERT_TRUE(r.typical_step.has_value());
  EXPECT_NEAR(*r.typical_step, 0.3, 0.05);
  std::size_t trusted = 0;
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const Eigen::Isometry3d e =
        relative(relative(*dataset.ground_truth(i), *dataset.ground_truth(i + 1)), r.steps[i].relative);
    if (!r.steps[i].trusted()) continue;
    ++trusted;
    EXPECT_LT(translation_norm(e), 0.3) << "step " << i << " says trusted";
    EXPECT_LT(rotation_angle(e) * kDegPerRad, 3.0) << "step " << i << " says trusted";
  }
  EXPECT_GE(trusted, 53u) << "90 % of the steps are believed";
  // The 10° turn between scans 3 and 4 is registered and believed.
  EXPECT_TRUE(r.steps[3].trusted()) << r.steps[3].quality.reason;
}

}  // namespace
}  // namespace sextant
