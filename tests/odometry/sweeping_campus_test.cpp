// Deskew with a known answer (issue 63): the synthetic campus driven fast, 10 m/s with a scan every
// metre at 10 Hz, by a lidar that sweeps while it moves (each point taken at its own time along the
// 0.1 s sweep from where the car then is, sensor.sweep_period) against the same route, seed and lidar
// scanning at once. Constant-velocity odometry, as a lidar alone runs it. The ground truth is exact.
//
// The car drives on a ground of 1 m facets (the campus' 4 m facets pitch and roll a car at 10 m/s by up
// to 1.7° from one metre to the next and back, a jolt a suspension would smooth and no constant velocity
// follows). On the first straight, the motion a constant velocity describes, the drift with deskew is no
// worse than the instantaneous scanner's (over four campus seeds: one seed's drift varies by a factor
// of three from a seed to the next either way); without deskew it is several times worse. Round the
// first corner, entered at once at 64°/s (the route's arcs start without a transition), and over the
// whole route with its corners eased in by clothoids (trajectory.corner_transition), deskew takes away
// most of what the sweep costs, not all: the target there is the disabled test at the end.
// Measured: docs/odometry.md, "Scans taken while moving".
#include <gtest/gtest.h>

#include <iostream>
#include <vector>

#include "sextant/eval/trajectory_metrics.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/synth/campus.hpp"

namespace sextant {
namespace {

constexpr int kRouteScans = 1258;  // the whole route (≈ 1,257 m) divided into scans a metre apart
constexpr int kStraight = 72;      // scans 0–71: the first straight, up to the first corner
constexpr int kCorner = 110;       // scans 0–109: the straight, the first corner and the next block side

synth::CampusDataset fast_campus(double sweep_period, int scans, std::uint64_t seed, double turn_deg,
                                 double corner_transition = 0.0) {
  synth::CampusSettings s;
  s.trajectory.corner_transition = corner_transition;
  s.trajectory.scans = kRouteScans;
  s.trajectory.first_scans = scans;
  s.trajectory.scan_period = 0.1;          // 10 Hz
  s.trajectory.sharp_turn_deg = turn_deg;  // the turn on the spot between scans 3 and 4
  s.world.ground_cell = 1.0;
  s.sensor.yaw_steps = 120;  // a coarser lidar than the default, for the test's time
  s.sensor.elevation_steps = 64;
  s.sensor.sweep_period = sweep_period;
  return synth::CampusDataset(synth::generate_campus(s, seed));
}

/// KITTI-style drift over 25–100 m segments [%] of a constant-velocity run.
double drift_percent(const synth::CampusDataset& dataset, bool deskew) {
  OdometrySettings s;
  s.guess = OdometryGuess::constant_velocity;  // a lidar alone: no odometer
  s.deskew = deskew;
  const OdometryResult r = run_odometry(dataset, s, 0, dataset.size());
  EXPECT_EQ(r.timed_scans, dataset.scan(0).has_time() ? dataset.size() : 0u);
  // Every scan, the first ones once a velocity is known (but one that left the map before, after an
  // untrusted first step).
  if (deskew) {
    EXPECT_GE(r.deskewed() + 1, r.timed_scans);
  } else {
    EXPECT_EQ(r.deskewed(), 0u);
  }
  std::vector<Eigen::Isometry3d> truth;
  for (std::size_t i = 0; i < dataset.size(); ++i) truth.push_back(*dataset.ground_truth(i));
  KittiDriftSettings segments;
  segments.segment_lengths = {25, 50, 75, 100};
  segments.step = 1;
  const KittiDriftResult k = kitti_drift(r.poses, truth, segments);
  EXPECT_TRUE(k.status.ok) << k.status.message;
  return 100.0 * k.translation;
}

struct Drifts {
  double instant = 0.0, skewed = 0.0, deskewed = 0.0;  ///< [%]
};

Drifts drifts(int scans, std::uint64_t seed, double turn_deg, double corner_transition = 0.0) {
  const synth::CampusDataset instant = fast_campus(0.0, scans, seed, turn_deg, corner_transition);
  const synth::CampusDataset sweeping = fast_campus(0.1, scans, seed, turn_deg, corner_transition);
  const Drifts d{drift_percent(instant, true), drift_percent(sweeping, false), drift_percent(sweeping, true)};
  std::cout << "campus seed " << seed << ", " << scans << " scans, corner transition " << corner_transition
            << " m: drift instantaneous " << d.instant << " %, sweeping without deskew " << d.skewed
            << " %, with deskew " << d.deskewed << " %\n";
  return d;
}

TEST(SweepingCampus, OnAStraightDeskewedDriftIsNoWorseThanAnInstantaneousScanners) {
  const synth::CampusDataset one = fast_campus(0.1, kStraight, 1, 0.01);
  EXPECT_NEAR((one.ground_truth(31)->translation() - one.ground_truth(30)->translation()).norm(), 1.0, 0.02)
      << "10 m/s at 10 Hz";
  EXPECT_TRUE(one.scan(3).has_time());
  Drifts mean;
  constexpr int kSeeds = 4;
  for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
    const Drifts d = drifts(kStraight, seed, 0.01);
    mean.instant += d.instant / kSeeds, mean.skewed += d.skewed / kSeeds,
        mean.deskewed += d.deskewed / kSeeds;
  }
  std::cout << "mean: instantaneous " << mean.instant << " %, without deskew " << mean.skewed
            << " %, with deskew " << mean.deskewed << " %\n";
  EXPECT_LE(mean.deskewed, 1.1 * mean.instant) << "deskew undoes the sweep";
  EXPECT_GT(mean.skewed, 3.0 * mean.deskewed) << "a sweep left as it is costs accuracy";
}

TEST(SweepingCampus, RoundACornerEnteredAtOnceDeskewTakesAwayMostOfTheSweepsCost) {
  const Drifts d = drifts(kCorner, 1, 2.0);
  EXPECT_LT(d.deskewed - d.instant, 0.35 * (d.skewed - d.instant));
}

/// The whole route (all 15 corners, each eased in and out by a 10 m clothoid: the yaw rate ramps up to
/// 64°/s over a second instead of jumping), seed 1, computed once for the tests below.
const Drifts& whole_route() {
  static const Drifts d = drifts(kRouteScans, 1, 2.0, 10.0);
  return d;
}

TEST(SweepingCampus, OverTheWholeRouteWithEasedCornersDeskewTakesAwayMostOfTheSweepsCost) {
  const Drifts& d = whole_route();
  // Measured 0.35 % deskewed, 0.14 % instantaneous, 1.8 % without deskew: 13 % of the sweep's cost left.
  EXPECT_LT(d.deskewed - d.instant, 0.25 * (d.skewed - d.instant));
}

// The target (63, item 2), not met today: deskewed 0.35 % against 0.14 % instantaneous. The sweep
// of a scan stamped at its start is the motion to the next scan, which no causal velocity knows round a
// corner: even the true velocity of the step before, or at the stamp, leaves most of the gap, while
// deskew by each sweep's true motion (an oracle) gives 0.20 % here, 1.43 × the instantaneous scanner's
// (a scan sampled from other places sends the registrations elsewhere): the tolerance, 1.5 ×. Measured:
// docs/odometry.md, "Scans taken while moving". To enable with a scheme that estimates each sweep's own
// motion (continuous-time registration).
TEST(SweepingCampus, DISABLED_OverTheWholeRouteDeskewedDriftIsNoWorseThanAnInstantaneousScanners) {
  const Drifts& d = whole_route();
  EXPECT_LE(d.deskewed, 1.5 * d.instant);
}

}  // namespace
}  // namespace sextant
