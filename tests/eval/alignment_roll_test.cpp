// The ATE's alignment on a nearly straight trajectory: the rotation about the line comes from the
// orientations where the positions leave it free (by more than kRollTolerance) and the orientations
// fix it better; nothing changes where the positions fix it.
#include <gtest/gtest.h>

#include <cmath>

#include "sextant/core/rng.hpp"
#include "sextant/eval/alignment_roll.hpp"
#include "sextant_test/random_draws.hpp"

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

/// The truth with `sigma` metres of position noise per axis and pose, orientations exact.
PoseList noisy(const PoseList& truth, std::uint64_t seed, double sigma = 0.5) {
  Rng rng(seed);
  PoseList out = truth;
  for (auto& T : out) T.translation() += test::normal_draws<3>(rng) * sigma;
  return out;
}

/// The positions of `poses`.
std::vector<Eigen::Vector3d> positions(const PoseList& poses) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& T : poses) out.push_back(T.translation());
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

TEST(AlignmentRoll, PositionsThatFixTheRollToADegreeAreLeftAlone) {
  // A winding road (±15 m sideways, 10.6 m RMS from its axis) with 5 cm of noise: the positions fix
  // the roll to about 0.085 m / 10.6 m = 0.5°.
  const PoseList truth = road(15.0);
  const PoseList estimate = noisy(truth, 3, 0.05);
  const Similarity3 plain = umeyama_alignment(positions(estimate), positions(truth), false);
  bool resolved = true;
  const Similarity3 out = resolve_roll_about_trajectory(plain, estimate, truth, &resolved);
  EXPECT_FALSE(resolved);
  EXPECT_TRUE(out.rotation.isApprox(plain.rotation));
  EXPECT_TRUE(out.translation.isApprox(plain.translation));
}

TEST(AlignmentRoll, OrientationsThatScatterMoreThanThePositionsDoNotOverrideThem) {
  // The same road with 0.5 m of noise leaves about 5° of roll free, but the orientations are turned
  // by up to ±60° about the road: they fix it worse, so the positions' roll stays.
  const PoseList truth = road(15.0);
  PoseList estimate = noisy(truth, 3);
  Rng rng(4);
  for (auto& T : estimate)
    T.linear() =
        Eigen::AngleAxisd(rng.uniform(-60.0, 60.0) * kDeg, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Similarity3 plain = umeyama_alignment(positions(estimate), positions(truth), false);
  bool resolved = true;
  const Similarity3 out = resolve_roll_about_trajectory(plain, estimate, truth, &resolved);
  EXPECT_FALSE(resolved);
  EXPECT_TRUE(out.rotation.isApprox(plain.rotation));
}

TEST(AlignmentRoll, APitchBowIsNotTakenForARoll) {
  // MulRan keyframes 10–30 in miniature: 21 poses over 50 m whose road bows 0.5 m sideways; the
  // estimate is right but for a pitch drift that bows it 0.2 m upwards. Rolling that bow onto the
  // road's fits the positions best, by atan(0.2 / 0.5) ≈ 22°: the positions fix the roll to only
  // about 5 cm / 0.16 m. The orientations are exact, so the roll comes from them and the ATE's
  // rotation error stays what the estimate's orientations have (none).
  PoseList truth, estimate;
  for (int k = 0; k <= 20; ++k) {
    const double x = 2.5 * k, bow = std::pow((x - 25.0) / 25.0, 2);
    truth.push_back(Eigen::Isometry3d(Eigen::Translation3d(x, 0.5 * bow, 0.0)));
    estimate.push_back(Eigen::Isometry3d(Eigen::Translation3d(x, 0.5 * bow, 0.2 * bow)));
  }
  const AteResult ate = absolute_trajectory_error(estimate, truth, Alignment::se3);
  ASSERT_TRUE(ate.status.ok);
  EXPECT_TRUE(ate.roll_from_orientations);
  EXPECT_LT(ate.rotation.max, 0.5 * kDeg);
  const Similarity3 plain = umeyama_alignment(positions(estimate), positions(truth), false);
  EXPECT_GT(Eigen::AngleAxisd(plain.rotation).angle(), 15.0 * kDeg);  // what Umeyama alone does
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
