// Corners eased in and out by clothoids (trajectory.corner_transition, issue 63): the route sampled
// every 5 cm without the lane wander, so that its geometry is exact. Known answers: the curvature
// (heading change per metre) ramps at 1 / (R · Ls) per metre up to 1 / R, where the plain arcs jump to
// 1 / R at once; the route still closes on its start (the tangent lengths place every eased corner
// between its two legs); the road engineer's shift p ≈ Ls² / 24R and k ≈ Ls / 2 for the tangent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "sextant/core/units.hpp"
#include "sextant/synth/route.hpp"

namespace sextant::synth {
namespace {

constexpr double kRadius = 9.0;

std::vector<RoutePoint> fine_route(double transition, int scans = 26000) {
  WorldSettings world;
  TrajectorySettings t;
  t.scans = scans;  // ≈ 5 cm apart on the ≈ 1.26 km route
  t.lateral_wander = 0.0;
  t.corner_radius = kRadius;
  t.corner_transition = transition;
  Rng rng(1);
  return sample_route(world, t, rng);
}

double wrapped(double angle) {
  return std::remainder(angle, 2.0 * kPi);
}

struct Curvature {
  double largest = 0.0;       ///< |dθ/ds| [1/m]
  double largest_rate = 0.0;  ///< |d²θ/ds²| [1/m²], between neighbouring 5 cm pieces
  double spacing = 0.0;       ///< [m]
};

/// The route's curvature from its headings, away from the turn on the spot between scans 3 and 4.
Curvature curvature(const std::vector<RoutePoint>& route) {
  Curvature c;
  c.spacing = (route[1].position - route[0].position).norm();
  std::vector<double> kappa;
  for (std::size_t i = 1; i < route.size(); ++i)
    kappa.push_back(wrapped(route[i].heading - route[i - 1].heading) / c.spacing);
  const std::size_t after_sharp_turn = static_cast<std::size_t>(std::ceil(12.0 / c.spacing));
  for (std::size_t i = after_sharp_turn; i < kappa.size(); ++i) {
    c.largest = std::max(c.largest, std::abs(kappa[i]));
    c.largest_rate = std::max(c.largest_rate, std::abs(kappa[i] - kappa[i - 1]) / c.spacing);
  }
  return c;
}

TEST(EasedCorners, CurvatureRampsUpToTheArcsInsteadOfJumping) {
  const Curvature plain = curvature(fine_route(0.0));
  EXPECT_NEAR(plain.largest, 1.0 / kRadius, 1e-3);
  // An arc's curvature arrives within one 5 cm piece: a rate of ≈ (1 / R) / 5 cm.
  EXPECT_GT(plain.largest_rate, 0.4 / (kRadius * plain.spacing));
  for (const double transition : {5.0, 10.0}) {
    const Curvature eased = curvature(fine_route(transition));
    EXPECT_NEAR(eased.largest, 1.0 / kRadius, 1e-3) << transition;
    // The clothoid's rate 1 / (R · Ls), with a little for where a piece straddles two pieces of the road.
    EXPECT_LT(eased.largest_rate, 1.05 / (kRadius * transition)) << transition;
    EXPECT_GT(eased.largest_rate, 0.95 / (kRadius * transition)) << transition;
  }
}

TEST(EasedCorners, TheRouteStillClosesOnItsStartAndStepsEvenly) {
  for (const double transition : {0.0, 7.0, 10.0}) {
    const std::vector<RoutePoint> route = fine_route(transition);
    EXPECT_LT(route.back().position.norm(), 1e-6) << transition;  // home at the origin
    EXPECT_NEAR(wrapped(route.back().heading + 0.5 * kPi), 0.0, 1e-9) << "arriving southwards";
    const double spacing = (route[1].position - route[0].position).norm();
    // From past the turn on the spot (a kink between scans 3 and 4 of the route, at 11 m).
    for (std::size_t i = static_cast<std::size_t>(12.0 / spacing); i < route.size(); ++i) {
      const double step = (route[i].position - route[i - 1].position).norm();
      ASSERT_LE(step, spacing + 1e-6) << transition << " at " << i;  // no jump where pieces meet
      ASSERT_GT(step, spacing * 0.99) << transition << " at " << i;  // a corner cuts no chord short
    }
  }
}

TEST(EasedCorners, TangentLengthIsTheRoadEngineersFormula) {
  const double quarter = 0.5 * kPi;
  EXPECT_DOUBLE_EQ(corner_tangent_length(kRadius, 0.0, quarter), kRadius * std::tan(0.5 * quarter));
  // Series for small Ls / R: p = Ls² / 24R − Ls⁴ / 2688R³, k = Ls / 2 − Ls³ / 240R².
  const double ls = 3.0;
  const double p = ls * ls / (24 * kRadius) - std::pow(ls, 4) / (2688 * std::pow(kRadius, 3));
  const double k = ls / 2 - std::pow(ls, 3) / (240 * kRadius * kRadius);
  EXPECT_NEAR(corner_tangent_length(kRadius, ls, quarter), (kRadius + p) * std::tan(0.5 * quarter) + k, 1e-5);
  // A transition longer than R θ is clamped: two clothoids and no arc.
  EXPECT_DOUBLE_EQ(corner_tangent_length(kRadius, 100.0, quarter),
                   corner_tangent_length(kRadius, kRadius * quarter, quarter));
}

TEST(EasedCorners, SettingsRefuseTransitionsThatDoNotFit) {
  CampusSettings s;
  std::string why;
  s.trajectory.corner_transition = 10.0;
  EXPECT_TRUE(s.valid(&why)) << why;
  s.trajectory.corner_transition = -1.0;
  EXPECT_FALSE(s.valid(&why));
  EXPECT_NE(why.find("corner_transition"), std::string::npos) << why;
  s.trajectory.corner_transition = 10.0;
  s.world.block_width = 26.0;  // two tangents of ≈ 14.4 m do not fit on a 26 m block side
  EXPECT_FALSE(s.valid(&why));
  EXPECT_NE(why.find("do not fit"), std::string::npos) << why;
  s.trajectory.corner_transition = 0.0;  // plain arcs: as before
  EXPECT_TRUE(s.valid(&why)) << why;
  s.trajectory.corner_radius = 0.0;
  s.trajectory.corner_transition = 2.0;
  EXPECT_FALSE(s.valid(&why));
}

}  // namespace
}  // namespace sextant::synth
