// The registration chained when none is trusted (suspect_choice.hpp): the fits choose a band, the
// motion prior chooses inside it; the alignment distance is the RMS displacement of the input.
#include <gtest/gtest.h>

#include <cmath>

#include "sextant/odometry/suspect_choice.hpp"

namespace sextant {
namespace {

Eigen::Isometry3d along_x(double metres) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation().x() = metres;
  return T;
}

PointCloud square_ring() {  // four points 10 m from the origin
  PointCloud cloud;
  for (const auto& p : {Eigen::Vector3f(10, 0, 0), Eigen::Vector3f(0, 10, 0), Eigen::Vector3f(-10, 0, 0),
                        Eigen::Vector3f(0, -10, 0)})
    cloud.push_back(p);
  return cloud;
}

TEST(SuspectChoice, AlignmentDistanceIsTheRmsDisplacement) {
  const PointCloud ring = square_ring();
  EXPECT_NEAR(alignment_distance(ring, along_x(3.0), along_x(-1.0)), 4.0, 1e-12);
  // A yaw of θ about the origin moves every point 10 m from it by 2·10·sin(θ/2).
  const double theta = 0.1;
  const Eigen::Isometry3d yaw(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(alignment_distance(ring, yaw, Eigen::Isometry3d::Identity()), 20.0 * std::sin(theta / 2), 1e-6);
  EXPECT_EQ(alignment_distance(PointCloud{}, yaw, along_x(1.0)), 0.0);
}

TEST(SuspectChoice, ThePriorChoosesAmongFitsThatAreAboutEqual) {
  // MulRan 33→34 in miniature: the lowest fit is far from the guess, one 5 % worse is near it.
  const std::vector<SuspectCandidate> candidates{
      {along_x(7.7), 1.38}, {along_x(-12.7), 1.44}, {along_x(0.7), 1.46}};
  EXPECT_EQ(choose_suspect(candidates, square_ring(), along_x(-13.1), 1.1), 1u);
}

TEST(SuspectChoice, AFitOutsideTheBandIsNotChosenHoweverNearTheGuess) {
  const std::vector<SuspectCandidate> candidates{{along_x(7.7), 1.30}, {along_x(-13.0), 1.60}};
  EXPECT_EQ(choose_suspect(candidates, square_ring(), along_x(-13.1), 1.1), 0u);
  // A band of 1 leaves only the lowest fit, wherever the guess is.
  const std::vector<SuspectCandidate> close{{along_x(7.7), 1.30}, {along_x(-13.0), 1.31}};
  EXPECT_EQ(choose_suspect(close, square_ring(), along_x(-13.1), 1.0), 0u);
  EXPECT_EQ(choose_suspect(close, square_ring(), along_x(-13.1), 1.1), 1u);
}

TEST(SuspectChoice, AnEqualDistanceGoesToTheLowerFit) {
  const std::vector<SuspectCandidate> candidates{{along_x(1.0), 1.40}, {along_x(-1.0), 1.35}};
  EXPECT_EQ(choose_suspect(candidates, square_ring(), Eigen::Isometry3d::Identity(), 1.1), 1u);
}

}  // namespace
}  // namespace sextant
