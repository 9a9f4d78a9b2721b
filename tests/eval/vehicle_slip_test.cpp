// A car's sideways slip per step: known answers on arcs driven with the sensor turned on the car.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sextant/eval/vehicle_slip.hpp"

namespace sextant {
namespace {

struct Arc {
  double length;     ///< along the path, negative in reverse [m]
  double turn;       ///< heading change [rad]
  double slip = 0;   ///< sideways displacement added at the step's mean heading, left positive [m]
  double climb = 0;  ///< height change [m]
};

/// Sensor poses (world ← sensor) of a car driving `arcs` from the origin, the sensor yawed by
/// `mounting` on the car and standing on its rear axle (the point that moves along the arc).
std::vector<Eigen::Isometry3d> drive(const std::vector<Arc>& arcs, double mounting) {
  const Eigen::Isometry3d mount(Eigen::AngleAxisd(mounting, Eigen::Vector3d::UnitZ()));
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double heading = 0.3;
  std::vector<Eigen::Isometry3d> poses;
  const auto pose = [&] {
    Eigen::Isometry3d car = Eigen::Isometry3d::Identity();
    car.translate(position).rotate(Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()));
    return car * mount;
  };
  poses.push_back(pose());
  for (const Arc& a : arcs) {
    // An arc's chord: length 2 sin(turn / 2) / curvature along the mean heading (the length itself
    // for a straight step).
    const double chord =
        std::abs(a.turn) < 1e-12 ? a.length : 2.0 * std::sin(0.5 * a.turn) * a.length / a.turn;
    const double mean = heading + 0.5 * a.turn;
    position += Eigen::Vector3d(chord * std::cos(mean) - a.slip * std::sin(mean),
                                chord * std::sin(mean) + a.slip * std::cos(mean), a.climb);
    heading += a.turn;
    poses.push_back(pose());
  }
  return poses;
}

const std::vector<Arc> kDrive = {{5.0, 0.05},      {8.0, -0.12},     {12.0, 0.0, 0.0, 0.3}, {3.0, 0.4},
                                 {0.2, 0.01},      {6.0, 0.02, 0.8}, {9.0, -0.3},           {-4.0, 0.1},
                                 {7.0, 0.0, -0.6}, {10.0, 0.08}};

TEST(VehicleSlip, ArcsDoNotSlipWhateverTheMounting) {
  for (const double mounting : {0.0, 0.5, -1.2, M_PI, 0.5 * M_PI}) {
    SCOPED_TRACE(mounting);
    std::vector<Arc> arcs = kDrive;
    for (Arc& a : arcs) a.slip = 0.0;
    const VehicleSlip s = vehicle_slip(drive(arcs, mounting));
    // The axis of travel: the car's forward (or backward) direction in the sensor frame.
    EXPECT_NEAR(std::sin(2.0 * (s.mounting + mounting)), 0.0, 1e-9);
    EXPECT_GT(s.mounting, -0.5 * M_PI);
    EXPECT_LE(s.mounting, 0.5 * M_PI);
    ASSERT_EQ(s.slip.size(), arcs.size());
    for (const double slip : s.slip) EXPECT_NEAR(slip, 0.0, 1e-9);
    EXPECT_TRUE(s.slipping(0.01).empty());
  }
}

TEST(VehicleSlip, FindsTheStepsThatSlipAndHowFar) {
  // kDrive slips 0.8 m left on step 5 and 0.6 m right on step 8; the mounting is estimated from
  // all steps, the two slipping ones included, and the median keeps it where the others say.
  const VehicleSlip s = vehicle_slip(drive(kDrive, 0.4));
  ASSERT_EQ(s.slip.size(), kDrive.size());
  EXPECT_EQ(s.slipping(0.5), (std::vector<std::size_t>{5, 8}));
  EXPECT_NEAR(std::abs(s.slip[5]), 0.8, 1e-9);
  EXPECT_NEAR(std::abs(s.slip[8]), 0.6, 1e-9);
  EXPECT_LT(s.slip[5] * s.slip[8], 0.0) << "opposite sides";
  for (std::size_t k : {0u, 1u, 2u, 3u, 4u, 6u, 7u, 9u}) EXPECT_NEAR(s.slip[k], 0.0, 1e-9) << k;
  EXPECT_TRUE(s.slipping(1.0).empty());
}

TEST(VehicleSlip, UnknownWithoutMotion) {
  const std::vector<Eigen::Isometry3d> still(4, Eigen::Isometry3d::Identity());
  const VehicleSlip s = vehicle_slip(still);
  EXPECT_TRUE(std::isnan(s.mounting));
  ASSERT_EQ(s.slip.size(), 3u);
  EXPECT_TRUE(std::isnan(s.slip[0]));
  EXPECT_TRUE(s.slipping(0.5).empty());
  EXPECT_TRUE(vehicle_slip({}).slip.empty());
}

}  // namespace
}  // namespace sextant
