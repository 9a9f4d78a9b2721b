// The ATE's alignment on a nearly straight trajectory: the rotation about the line comes from the
// orientations (the positions leave it free), and nothing changes where the positions fix it.
#include <gtest/gtest.h>

#include <cmath>

#include "sextant/core/rng.hpp"
#include "sextant/eval/alignment_roll.hpp"

namespace sextant {
namespace {

constexpr double kDeg = M_PI / 180.0;

/// 100 poses 1 m apart along x with `wiggle` metres of sideways sine, facing along x.
PoseList road(double wiggle) {
  PoseList poses;
  for (int k = 0; k < 100; ++k)
    poses.push_back(Eigen::Isometry3d(Eigen::Translation3d(k, wiggle * std::sin(k / 10.0), 0.01 * k)));
  return poses;
}

/// The truth with 0.5 m of position noise per pose, orientations exact.
PoseList noisy(const PoseList& truth, std::uint64_t seed) {
  Rng rng(seed);
  PoseList out = truth;
  for (auto& T : out) T.translation() += Eigen::Vector3d(rng.normal(), rng.normal(), rng.normal()) * 0.5;
  return out;
}

TEST(AlignmentRoll, AStraightRoadTakesItsRollFromTheOrientations) {
  const PoseList truth = road(0.2);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const PoseList estimate = noisy(truth, seed);
    const AteResult ate = absolute_trajectory_error(estimate, truth, Alignment::se3);
    ASSERT_TRUE(ate.status.ok);
    EXPECT_TRUE(ate.roll_from_orientations) << seed;
    EXPECT_LT(ate.rotation.rms, 2.0 * kDeg) << seed;  // the orientations are exact
    EXPECT_LT(ate.translation.rms, 1.0) << seed;      // √3 · 0.5 m of noise, less what the fit absorbs
  }
}

TEST(AlignmentRoll, PositionsThatFixTheRotationAreLeftAlone) {
  const PoseList truth = road(15.0);  // a winding road: ±15 m sideways
  const PoseList estimate = noisy(truth, 3);
  std::vector<Eigen::Vector3d> src, dst;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    src.push_back(estimate[i].translation());
    dst.push_back(truth[i].translation());
  }
  const Similarity3 plain = umeyama_alignment(src, dst, false);
  bool resolved = true;
  const Similarity3 out = resolve_roll_about_trajectory(plain, estimate, truth, &resolved);
  EXPECT_FALSE(resolved);
  EXPECT_TRUE(out.rotation.isApprox(plain.rotation));
  EXPECT_TRUE(out.translation.isApprox(plain.translation));
}

TEST(AlignmentRoll, TheResolvedRollIsTheOrientationsOffset) {
  // The estimate is the truth turned 40° about the road (x) through its centroid: positions on a
  // line cannot see that turn, the orientations can, and the alignment must undo exactly it.
  const PoseList truth = road(0.0);
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& T : truth) centroid += T.translation();
  centroid /= double(truth.size());
  const Eigen::Isometry3d turn = Eigen::Translation3d(centroid) *
                                 Eigen::AngleAxisd(40.0 * kDeg, Eigen::Vector3d::UnitX()) *
                                 Eigen::Translation3d(-centroid);
  PoseList estimate;
  for (const auto& T : truth) estimate.push_back(turn * T);
  const AteResult ate = absolute_trajectory_error(noisy(estimate, 9), truth, Alignment::se3);
  EXPECT_TRUE(ate.roll_from_orientations);
  EXPECT_LT(ate.rotation.max, 0.5 * kDeg);
}

}  // namespace
}  // namespace sextant
