// Odometry on a real sequence (issue 22): a short stretch of the shared MulRan Riverside02 excerpt
// (Ouster OS1-64 on a car; ../shared/data, whose reference is good to a few cm on 0–107 but for
// keyframes 33→35), read as a plain folder of scans. Right or say so: no step more than 1 m or 5° off
// the reference is trusted where the reference is a car's path.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "sextant/core/dataset.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/vehicle_slip.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/matcher_choice.hpp"
#include "sextant/matchers/matcher_traits.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/register_pair.hpp"
#include "sextant/matchers/sampler.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant_test/temp_dir.hpp"
#include "shared_mulran.hpp"

namespace sextant {
namespace {

using test::kMulran;
using test::kReferenceSlip;
using test::mulran_excerpt;
using test::reference_slip;
using test::trusted_steps_expecting_them_right;

// Where the reference is not a car's path it cannot judge: the whole excerpt's reference slips more than
// kReferenceSlip sideways between the stretches (109–116, where the data's README calls it wrong) and on
// keyframes 33→34 and 34→35, by 1.1–1.3 m against their turn. A car turning 2.1° over 13.7 m moves
// 0.25 m towards the turn; the reference moves it 0.76 m the other way. Every other step of 0–107 and
// 116–165 slips at most 0.2 m.
TEST(RealSequence, MulranReferenceIsACarsPathButOnKeyframes33To35AndBetweenTheStretches) {
  if (!std::filesystem::is_directory(kMulran)) GTEST_SKIP() << "no " << kMulran;
  const auto dataset = open_dataset(kMulran);
  const VehicleSlip slip = reference_slip(*dataset, 0, dataset->size() - 1);
  EXPECT_EQ(slip.slipping(kReferenceSlip),
            (std::vector<std::size_t>{33, 34, 109, 110, 111, 112, 113, 114, 115}));
  EXPECT_LT(std::abs(slip.mounting) * kDegPerRad, 2.0) << "the car drives along the sensor's x axis";
  for (std::size_t k = 0; k < slip.slip.size(); ++k) {
    if ((k < 107 || k >= 116) && k != 33 && k != 34) {
      EXPECT_LT(std::abs(slip.slip[k]), 0.2) << k;
    }
  }
  EXPECT_GT(std::abs(slip.slip[33]), 1.0);
  EXPECT_GT(std::abs(slip.slip[34]), 1.0);
}

TEST(RealSequence, MulranStretchIsRightOrSaysSo) {
  if (!std::filesystem::is_directory(kMulran)) GTEST_SKIP() << "no " << kMulran;
  const auto dataset = open_dataset(kMulran);
  ASSERT_EQ(dataset->metadata().format, "folder");
  ASSERT_EQ(dataset->size(), 166u);
  ASSERT_TRUE(dataset->metadata().has_ground_truth);
  ASSERT_TRUE(dataset->stamp(0).has_value());
  // Keyframes 26–40: the car speeds up to 10 m/s, keyframes 3–14 m apart, 0.3–1.4 s.
  OdometrySettings s;
  s.guess = OdometryGuess::constant_velocity;
  s.map = OdometryMap::scan;
  const std::size_t first = 26, count = 15;
  const OdometryResult r = run_odometry(*dataset, s, first, count);
  ASSERT_EQ(r.steps.size(), count - 1);
  const std::size_t trusted = trusted_steps_expecting_them_right(*dataset, r, first);
  for (const OdometryStep& step : r.steps) {
    if (!step.trusted()) {
      EXPECT_FALSE(step.recovery.empty()) << "an untrusted step records how it was chained";
    }
  }
  EXPECT_GE(trusted, count / 2) << "most steps of a drive are registered and believed";
  EXPECT_EQ(r.untrusted(), r.steps.size() - trusted);
  // Keyframes 31→32 (0.5 s, 7.9 m, where the last trusted motion says 14 m): the registration from
  // the constant-velocity guess is not trusted, so the step is recovered (with the precision stage
  // the wide basin finds a trusted pose; before it, only the least suspect registration was left)
  // and lands within 0.5 m where the guess was 6.2 m off.
  const OdometryStep& step = r.steps[31 - first];
  EXPECT_FALSE(step.recovery.empty()) << "the guess's registration was not believed";
  const Eigen::Isometry3d truth = relative(*dataset->ground_truth(31), *dataset->ground_truth(32));
  EXPECT_LT(translation_norm(relative(truth, step.relative)), 0.5);
}

// The local map is right or says so too: after the untrusted step 31→32 its scan is placed by a
// doubtful motion, so the map starts again from it; before, steps 33→37 registered against a map
// holding that misplaced scan, fitted it, and said trusted while 3–22 m off. The local map is the
// default.
TEST(RealSequence, MulranLocalMapIsRightOrSaysSo) {
  if (!std::filesystem::is_directory(kMulran)) GTEST_SKIP() << "no " << kMulran;
  const auto dataset = open_dataset(kMulran);
  OdometrySettings s;
  s.guess = OdometryGuess::constant_velocity;
  ASSERT_EQ(s.map, OdometryMap::local_map);
  const std::size_t first = 26, count = 15;
  const OdometryResult r = run_odometry(*dataset, s, first, count);
  ASSERT_EQ(r.steps.size(), count - 1);
  const std::size_t trusted = trusted_steps_expecting_them_right(*dataset, r, first);
  EXPECT_GE(trusted, count / 2) << "most steps of a drive are registered and believed";
  // Keyframes 33→34 and 34→35 (13.7 and 10.0 m along a straight road), where the reference slips
  // sideways 1.1 and 1.2 m, as a car cannot (trusted_steps_expecting_them_right leaves them unjudged).
  // After an untrusted step the next one searches, and two searches agree on both: 9.8 and 9.5 m/s,
  // between the 10.1 and 9.2 m/s of the steps around them (the reference: 10.5 and 11.1 m/s). Neither
  // may lie 2 m from the reference (once a wide-basin pose 21 m off, running backwards, fitted best).
  for (const std::size_t k : {33u, 34u}) {
    const Eigen::Isometry3d truth = relative(*dataset->ground_truth(k), *dataset->ground_truth(k + 1));
    EXPECT_LT(translation_norm(relative(truth, r.steps[k - first].relative)), 2.0) << "step " << k;
  }
}

// Every other keyframe of 0–6 with their times: the car starts from rest, so velocity × Δt of the
// first step (0.96 m) lies 4 m short of the next one (5.1 m), while the last motion per keyframe
// (5.0 m) is right. Both priors are registered (StepWorker::first_try): each passes the checks, 4 m
// apart, so the first registration is ambiguous and the wide basin recovers the step; its answer fits
// clearly better than the wrong prior's (StepWorker::recover), so it corrects the step. Before, the
// registration from velocity × Δt was trusted 3.6 m off, and over the whole stretch read every other
// keyframe 27 trusted steps 3–24 m off followed it (bench/variants.sh).
TEST(RealSequence, MulranEveryOtherKeyframeIsRightOrSaysSo) {
  if (!std::filesystem::is_directory(kMulran)) GTEST_SKIP() << "no " << kMulran;
  test::TempDir tmp;
  const std::size_t n = 4;
  const auto dataset = mulran_excerpt(tmp.path(), {0, 2, 4, 6}, true);
  ASSERT_EQ(dataset->size(), n);
  ASSERT_TRUE(dataset->stamp(0).has_value());
  OdometrySettings s;
  s.guess = OdometryGuess::constant_velocity;  // the CLI's default for a dataset without odometry
  const OdometryResult r = run_odometry(*dataset, s, 0, n);
  ASSERT_EQ(r.steps.size(), n - 1);
  const std::size_t trusted = trusted_steps_expecting_them_right(*dataset, r, 0);
  EXPECT_GE(trusted, n / 2) << "most steps of a drive are registered and believed";
  const OdometryStep& step = r.steps[1];
  EXPECT_GT(translation_norm(relative(step.guess, r.steps[0].relative)), 3.0) << "velocity × Δt lies short";
  EXPECT_EQ(step.first_trust, Trust::kSuspect) << "two priors, two answers";
  EXPECT_EQ(step.recovery, "wide_basin");
  EXPECT_TRUE(step.trusted()) << step.quality.reason;
  const Eigen::Isometry3d truth = relative(*dataset->ground_truth(1), *dataset->ground_truth(2));
  EXPECT_LT(translation_norm(relative(truth, step.relative)), 0.1);
  // What the first registration said stays in the step (steps.csv's first_* columns): from
  // velocity × Δt (0.96 m) it slid to 1.5 m, 3.6 m short.
  EXPECT_GT(translation_norm(relative(truth, step.first_relative)), 2.0)
      << "the wide basin's pose, not the first";
  EXPECT_GT(step.first_relative.translation().norm(), 1.0) << "a registration's answer, not the identity";
}

// Keyframes 165 down to 154, backwards (the older keyframe into the newer one's frame), no times: no
// motion is known at first, and registrations slid back to zero motion pass the fit check (fit 1.2–1.29
// against 1.0–1.2 for right ones). Keyframes 155←154 register to 6.8 m (right) and, from another start,
// to zero motion, both passing; the wide basin's zero-motion answer then fits no clearly better than
// those, so it is a second answer and the step says so (StepWorker::recover). Before, it was taken as
// trusted, and every later step stayed at zero motion, trusted, 5–8 m off.
// Seed 3 draws the GBS samples with which the first steps end at no motion (the lidar rings
// coincide) and the fifth passes the absolute checks at a fit of 1.28: before
// check_unconfirmed_no_motion the chain then stood still, six wrong steps trusted.
TEST(RealSequence, MulranBackwardsIsRightOrSaysSo) {
  if (!std::filesystem::is_directory(kMulran)) GTEST_SKIP() << "no " << kMulran;
  test::TempDir tmp;
  std::vector<std::size_t> keyframes;
  for (std::size_t i = 165; i >= 154; --i) keyframes.push_back(i);
  const std::size_t n = keyframes.size();
  const auto dataset = mulran_excerpt(tmp.path(), keyframes, false);
  ASSERT_FALSE(dataset->stamp(0).has_value());
  for (const std::uint64_t seed : {1u, 3u}) {
    SCOPED_TRACE("GBS seed " + std::to_string(seed));
    OdometrySettings s;
    s.guess = OdometryGuess::constant_velocity;
    s.seed = seed;
    const OdometryResult r = run_odometry(*dataset, s, 0, n);
    ASSERT_EQ(r.steps.size(), n - 1);
    const std::size_t trusted = trusted_steps_expecting_them_right(*dataset, r, 0);
    EXPECT_GE(trusted, 3u) << "a few steps are registered and believed";
  }
}

// A plain chain of another matcher says which steps may be wrong (judged_matcher.hpp): point-to-plane
// ICP from no motion on keyframes 116–127, recovery off, stays near no motion while the car drives
// 6–8 m per keyframe. Its own correspondences overlap well, so before its poses were judged on the
// default ML-NDT's last layer every converged step passed; there they fit 1.44–1.55 × the prediction.
TEST(RealSequence, APlainIcpChainSaysItStoodStill) {
  if (!std::filesystem::is_directory(kMulran)) GTEST_SKIP() << "no " << kMulran;
  const auto dataset = open_dataset(kMulran);
  OdometrySettings s;
  s.registration.matcher = matcher_choice(IcpP2lSettings{});
  s.guess = OdometryGuess::constant_velocity;
  s.map = OdometryMap::scan;
  s.common_view = matcher_traits("icp_p2l").common_view_by_default;
  s.recover = false;
  const std::size_t first = 116, count = 12;
  const OdometryResult r = run_odometry(*dataset, s, first, count);
  ASSERT_EQ(r.steps.size(), count - 1);
  trusted_steps_expecting_them_right(*dataset, r, first);
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const Eigen::Isometry3d truth =
        relative(*dataset->ground_truth(first + i), *dataset->ground_truth(first + i + 1));
    wrong += translation_norm(relative(truth, r.steps[i].relative)) > 1.0;
  }
  EXPECT_GE(wrong, 8u) << "the chain stands still: a case for the checks";
  EXPECT_EQ(r.recovered(), 0u);
}

// A good guess stays good: from the reference pose, the default ML-NDT ends within the reference's
// own accuracy on MulRan pairs at walking pace and at speed (issue 22, "ML-NDT keeps a good guess"):
// refine_first runs the last layer from the guess and the precision stage refines it (measured
// 0.5–5.4 cm; from start layer 2 the coarse layers pulled 30→31 20.6 cm away, and the old outdoor
// preset 1.5–7 m). Backwards too (the older keyframe into the newer one's frame): there the coarse
// layers' run slid 7–8 m back to zero motion with a lower score (its lidar rings coincide with the
// reference's), and it won until a run that passes the trust checks came first (165←164, 107←106,
// 125←124). The bound is the reference's accuracy: point-to-plane ICP moves its pairs by 2–7 cm
// (../shared/data/README.md).
TEST(RealSequence, MulranPairsFromTheReferenceStayThere) {
  if (!std::filesystem::is_directory(kMulran)) GTEST_SKIP() << "no " << kMulran;
  const auto dataset = open_dataset(kMulran);
  const std::pair<std::size_t, std::size_t> pairs[] = {{1, 2},     {30, 31},   {120, 121}, {150, 151},
                                                       {165, 164}, {107, 106}, {125, 124}};
  for (const auto& [reference, input] : pairs) {
    const Eigen::Isometry3d truth =
        relative(*dataset->ground_truth(reference), *dataset->ground_truth(input));
    MlndtMatcher matcher;
    const auto gbs = make_sampler(GridSamplerSettings{});
    Rng rng(1);
    const PairMatch m = match_pair(matcher, *gbs, dataset->scan(reference), dataset->scan(input), truth, rng);
    const Eigen::Isometry3d error = relative(truth, m.result.T);
    EXPECT_LT(translation_norm(error), 0.07)
        << "pair " << reference << "←" << input << ": " << m.result.summary();
  }
}

/// `sextant match` from the identity (register_pair) of a MulRan keyframe into another, and how far it
/// ends from the reference's relative pose.
struct PairFromTheIdentity {
  PairRegistration registration;
  double metres_off = 0.0;
};

/// Keyframe `input` matched into keyframe `reference` from the identity; fails the test where the
/// result is more than 1 m or 5° off and says trusted.
PairFromTheIdentity matched_from_the_identity(const Dataset& dataset, std::size_t reference,
                                              std::size_t input) {
  const Eigen::Isometry3d truth = relative(*dataset.ground_truth(reference), *dataset.ground_truth(input));
  PairFromTheIdentity pair{register_pair(dataset.scan(reference), dataset.scan(input), {})};
  const Eigen::Isometry3d error = relative(truth, pair.registration.match.result.T);
  pair.metres_off = translation_norm(error);
  const bool wrong = pair.metres_off > 1.0 || rotation_angle(error) * kDegPerRad > 5.0;
  EXPECT_FALSE(wrong && pair.registration.match.result.quality.trusted())
      << "pair " << reference << "←" << input << " is " << pair.metres_off << " m off and says trusted";
  return pair;
}

// Right or say so from the identity, as `sextant match A B` registers (register_pair: the wide basin):
// keyframes registered backwards, 3–8 m apart along the road. 160←159 was trusted 8 m off: the
// wide basin's start at the guess slid to zero motion and won on its score, while its hypothesis at
// 6 m, refined from the layer it was scored at, ends 5 cm from the reference and passes too, so the
// result is ambiguous. Half of these pairs end right (before, with every hypothesis refined from
// start layer 2: 4 of the 12), and none ends wrong and trusted.
TEST(RealSequence, MulranPairsFromTheIdentityAreRightOrSaySo) {
  if (!std::filesystem::is_directory(kMulran)) GTEST_SKIP() << "no " << kMulran;
  const auto dataset = open_dataset(kMulran);
  const std::pair<std::size_t, std::size_t> pairs[] = {{165, 164}, {164, 163}, {107, 106}, {160, 159},
                                                       {141, 140}, {51, 50},   {30, 29},   {10, 9},
                                                       {125, 124}, {91, 90},   {164, 165}, {60, 61}};
  std::size_t right = 0;
  for (const auto& [reference, input] : pairs) {
    if (matched_from_the_identity(*dataset, reference, input).metres_off < 0.1) ++right;
  }
  EXPECT_GE(right, 6u) << "half end right";
}

// Keyframes 13–15 m apart, from the identity: the whole input ranks the hypotheses about no translation
// best, where a lidar's ground rings lie on each other, and the search's four candidates all slid there
// (18→21 ended 11.7 m off, 27→30 13.4 m; both said suspect). The points above the horizon, which hold
// no ground ring, rank the prescreened hypotheses anew, and their best, refined too, end at the
// reference (bench/pairs_from_identity.py).
TEST(RealSequence, PairsFarApartAreFoundByThePointsAboveTheHorizon) {
  if (!std::filesystem::is_directory(kMulran)) GTEST_SKIP() << "no " << kMulran;
  const auto dataset = open_dataset(kMulran);
  for (const auto& [reference, input] : {std::pair<std::size_t, std::size_t>{18, 21}, {27, 30}}) {
    const PairFromTheIdentity pair = matched_from_the_identity(*dataset, reference, input);
    EXPECT_LT(pair.metres_off, 0.2) << "pair " << reference << "←" << input;
    EXPECT_TRUE(pair.registration.match.result.quality.trusted())
        << pair.registration.match.result.quality.reason;
  }
}

// Keyframes 19–32 m apart along a riverside road whose rows of trees repeat, from the identity: the truth
// lies beyond the search's ±16 m, and the whole scan fits 1.27–1.29 × the prediction at no translation,
// better than at the reference's pose, where the ground's rings lie on each other. 148→151 and 148→153
// were trusted 19 and 32 m off with every seed. The points above the horizon fit clearly worse there
// (1.58–1.64): the answer says suspect (check_no_motion_above_horizon).
TEST(RealSequence, PairsBeyondTheSearchSaySo) {
  if (!std::filesystem::is_directory(kMulran)) GTEST_SKIP() << "no " << kMulran;
  const auto dataset = open_dataset(kMulran);
  for (const auto& [reference, input] :
       {std::pair<std::size_t, std::size_t>{148, 151}, {148, 153}, {100, 103}, {156, 160}}) {
    matched_from_the_identity(*dataset, reference, input);
  }
}

}  // namespace
}  // namespace sextant
