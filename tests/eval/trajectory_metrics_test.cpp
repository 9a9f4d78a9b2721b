#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sextant/core/pose.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/eval/trajectory_metrics.hpp"
#include "sextant_test/random_draws.hpp"

namespace sextant {
namespace {

Eigen::Isometry3d at(double x, double y, double z = 0.0) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

PoseList line_1d(std::initializer_list<double> xs) {
  PoseList poses;
  for (double x : xs) poses.push_back(at(x, 0));
  return poses;
}

// E18, thesis table 6.1 (§6.3): truth 0, 4, 8, 12; case 1 steps 1, 7, 4 (eq. 6.11 prints 4, 7, 4,
// a typo: its own sum (4−1)² + (7−4)² and the Wulf value need the estimate 0, 1, 8, 12).
TEST(ThesisTable61, OneDimensionalCases) {
  const PoseList truth = line_1d({0, 4, 8, 12});
  const PoseList cases[3] = {line_1d({0, 1, 8, 12}), line_1d({0, 5, 8, 12}), line_1d({0, 4, 8, 13})};
  const double wulf[3] = {1.5, 0.5, 0.5};         // eqs. (6.7)–(6.9)
  const double kummerle[3] = {2.45, 0.82, 0.58};  // eqs. (6.14)–(6.16), printed to 2 decimals
  const double kummerle_exact[3] = {std::sqrt(6.0), std::sqrt(2.0 / 3.0), std::sqrt(1.0 / 3.0)};
  for (int c = 0; c < 3; ++c) {
    const WulfResult w = wulf_metric(cases[c], truth);
    const KummerleResult k = kummerle_metric(cases[c], truth);
    ASSERT_TRUE(w.status.ok && k.status.ok) << c;
    EXPECT_DOUBLE_EQ(w.position_rms, wulf[c]) << "case " << c + 1;
    EXPECT_DOUBLE_EQ(w.orientation_rms, 0.0);
    EXPECT_NEAR(k.translation_rms, kummerle_exact[c], 1e-12) << "case " << c + 1;
    EXPECT_NEAR(std::round(k.translation_rms * 100.0) / 100.0, kummerle[c], 1e-12) << "case " << c + 1;
    EXPECT_EQ(k.translation_errors.size(), 3u);
  }
}

// E18, thesis table 6.2: truth (0,0), (5,1), (6,0); case 1 (0,0), (1,1), (6,0); case 2 (0,0), (5,−1), (6,0).
TEST(ThesisTable62, TwoDimensionalCases) {
  const PoseList truth{at(0, 0), at(5, 1), at(6, 0)};
  const PoseList case1{at(0, 0), at(1, 1), at(6, 0)};
  const PoseList case2{at(0, 0), at(5, -1), at(6, 0)};
  const WulfResult w1 = wulf_metric(case1, truth), w2 = wulf_metric(case2, truth);
  EXPECT_NEAR(w1.position_rms, std::sqrt(16.0 / 3.0), 1e-12);  // eq. (6.19)
  EXPECT_NEAR(w2.position_rms, std::sqrt(4.0 / 3.0), 1e-12);   // eq. (6.25)
  EXPECT_NEAR(std::round(w1.position_rms * 100.0) / 100.0, 2.31, 1e-12);
  EXPECT_NEAR(std::round(w2.position_rms * 100.0) / 100.0, 1.15, 1e-12);
  EXPECT_NEAR(kummerle_metric(case1, truth).translation_rms, 4.0, 1e-12);  // eq. (6.22)
  EXPECT_NEAR(kummerle_metric(case2, truth).translation_rms, 2.0, 1e-12);  // eq. (6.28)
}

TEST(Wulf, OrientationUsesWrappedEulerDifferences) {
  const PoseList ref{to_isometry(Pose6{0, 0, 0, 0, 0, M_PI - 0.05})};
  const PoseList est{to_isometry(Pose6{0, 0, 0, 0.03, 0, -M_PI + 0.05})};
  const WulfResult w = wulf_metric(est, ref);
  EXPECT_NEAR(w.orientation_rms, std::sqrt(0.03 * 0.03 + 0.1 * 0.1), 1e-9);  // eq. (6.3)
}

TEST(Kummerle, GivenRelationsWithReferenceMotions) {
  const PoseList est{at(0, 0), at(1, 0), at(2, 0)};
  PoseRelation loop{0, 2, true, at(2.5, 0)};  // a manually verified relation
  const KummerleResult k = kummerle_metric(est, {}, {loop});
  ASSERT_TRUE(k.status.ok);
  EXPECT_NEAR(k.translation_rms, 0.5, 1e-12);
  const KummerleResult bad = kummerle_metric(est, {}, {PoseRelation{0, 1, false, {}}});
  EXPECT_FALSE(bad.status.ok);
  EXPECT_FALSE(kummerle_metric(est, PoseList{at(0, 0)}).status.ok);  // length mismatch
}

TEST(Kummerle, RotationSeparately) {
  const PoseList ref{at(0, 0), at(1, 0)};
  PoseList est = ref;
  est[1].linear() = rotation_from_euler(0, 0, 0.2);
  const KummerleResult k = kummerle_metric(est, ref);
  EXPECT_NEAR(k.rotation_rms, 0.2, 1e-9);
  EXPECT_NEAR(k.translation_rms, 0.0, 1e-12);
}

TEST(Umeyama, RecoversKnownSimilarity) {
  Rng rng(7);
  std::vector<Eigen::Vector3d> src, dst;
  const Eigen::Matrix3d R = rotation_from_euler(0.3, -0.7, 2.1);
  const Eigen::Vector3d t(4.0, -2.0, 1.5);
  const double s = 1.7;
  for (int i = 0; i < 20; ++i) {
    src.push_back(test::uniform_draws<3>(rng, {-10, -10, -2}, {10, 10, 2}));
    dst.push_back(s * R * src.back() + t);
  }
  const Similarity3 sim = umeyama_alignment(src, dst, true);
  ASSERT_TRUE(sim.ok);
  EXPECT_NEAR(sim.scale, s, 1e-10);
  EXPECT_LT((sim.rotation - R).norm(), 1e-10);
  EXPECT_LT((sim.translation - t).norm(), 1e-9);
  for (auto& p : dst) p = R * (p - t) / s;  // now dst = R·R·src rigidly, no scale
  const Similarity3 rigid = umeyama_alignment(src, dst, false);
  EXPECT_DOUBLE_EQ(rigid.scale, 1.0);
  EXPECT_LT((rigid.rotation - R * R).norm(), 1e-10);
  EXPECT_FALSE(umeyama_alignment({src[0]}, {dst[0]}, true).ok);
}

PoseList square_path(std::size_t n) {
  PoseList poses;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = rotation_from_euler(0, 0, a + M_PI / 2);
    T.translation() = Eigen::Vector3d(10 * std::cos(a), 5 * std::sin(a), 0.1 * static_cast<double>(i));
    poses.push_back(T);
  }
  return poses;
}

TEST(Ate, AlignmentRemovesRigidAndScaleOffsets) {
  const PoseList ref = square_path(40);
  const Eigen::Isometry3d offset = to_isometry(Pose6{3, -1, 2, 0.1, 0.2, 0.9});
  PoseList rigid, scaled;
  for (const auto& T : ref) {
    rigid.push_back(offset * T);
    Eigen::Isometry3d S = T;
    S.translation() *= 0.5;
    scaled.push_back(S);
  }
  const AteResult none = absolute_trajectory_error(rigid, ref, Alignment::none);
  EXPECT_GT(none.translation.rms, 1.0);
  const AteResult se3 = absolute_trajectory_error(rigid, ref, Alignment::se3);
  ASSERT_TRUE(se3.status.ok);
  EXPECT_LT(se3.translation.rms, 1e-9);
  EXPECT_LT(se3.rotation.max, 1e-6);
  const AteResult sim3 = absolute_trajectory_error(scaled, ref, Alignment::sim3);
  EXPECT_NEAR(sim3.alignment.scale, 2.0, 1e-9);
  EXPECT_LT(sim3.translation.rms, 1e-9);
  EXPECT_GT(absolute_trajectory_error(scaled, ref, Alignment::se3).translation.rms, 0.1);
}

TEST(Rpe, EvoPairSelection) {
  PoseList line;
  for (int i = 0; i < 10; ++i) line.push_back(at(i, 0));
  RpeSettings frames;
  frames.delta = 3;
  using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;
  EXPECT_EQ(rpe_pairs(line, frames), (Pairs{{0, 3}, {3, 6}, {6, 9}}));
  frames.all_pairs = true;
  EXPECT_EQ(rpe_pairs(line, frames).size(), 7u);
  RpeSettings meters;
  meters.unit = RpeSettings::Unit::meters;
  meters.delta = 2.0;
  EXPECT_EQ(rpe_pairs(line, meters), (Pairs{{2, 4}, {4, 6}, {6, 8}}));
  meters.all_pairs = true;
  EXPECT_EQ(rpe_pairs(line, meters).size(), 8u);  // (0,2) … (7,9); from 8 the best is 9 at 1 m
  frames.delta = 2.5;
  EXPECT_FALSE(frames.valid(nullptr));
  // Issue 64, class 7: a step past the poses gives no pair; one near 2⁶⁴ used to wrap i + step
  // around and loop for ever. Past 2⁵³ frames the delta is refused.
  frames.delta = 9;
  EXPECT_EQ(rpe_pairs(line, frames), (Pairs{{0, 9}}));
  frames.delta = 10;
  EXPECT_TRUE(rpe_pairs(line, frames).empty());
  frames.delta = 9007199254740992.0;  // 2⁵³
  EXPECT_TRUE(frames.valid(nullptr));
  EXPECT_TRUE(rpe_pairs(line, frames).empty());
  frames.all_pairs = false;
  EXPECT_TRUE(rpe_pairs(line, frames).empty());
  frames.delta = 1e300;
  std::string why;
  EXPECT_FALSE(frames.valid(&why));
  EXPECT_EQ(why, "delta in frames must be at most 2^53");
  meters.tolerance = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(meters.valid(nullptr));
}

TEST(Rpe, ConstantStepErrorGivesConstantRelativeError) {
  PoseList ref, est;
  for (int i = 0; i < 11; ++i) {
    ref.push_back(at(i, 0));
    est.push_back(at(1.1 * i, 0));
  }
  RpeSettings s;
  s.delta = 2;
  const RpeResult r = relative_pose_error(est, ref, s);
  ASSERT_TRUE(r.status.ok);
  EXPECT_EQ(r.pairs.size(), 5u);
  EXPECT_NEAR(r.translation.mean, 0.2, 1e-12);
  EXPECT_NEAR(r.translation.std, 0.0, 1e-12);
  EXPECT_FALSE(relative_pose_error(est, PoseList{}, s).status.ok);
}

/// `count` poses from the identity, pose i + 1 = pose i · step(i).
template <class Step>
PoseList chained(int count, Step step) {
  PoseList poses{Eigen::Isometry3d::Identity()};
  for (int i = 0; i + 1 < count; ++i) poses.push_back(poses.back() * step(i));
  return poses;
}

// Every step pitched up by the same 0.1° is a bias many standard errors from 0; steps pitched up and
// down by 0.1° in turn have the same unsigned RPE but no bias.
TEST(Rpe, SignedMeanSeparatesABiasFromNoise) {
  const double pitch = 0.1 * std::acos(-1.0) / 180.0;
  for (const bool alternating : {false, true}) {
    const PoseList ref = chained(21, [](int) { return at(1.0, 0.0); });
    const PoseList est = chained(21, [&](int i) {
      const double sign = alternating && i % 2 == 1 ? -1.0 : 1.0;
      return at(1.0, 0.0) * Eigen::AngleAxisd(sign * pitch, Eigen::Vector3d::UnitY());
    });
    const RpeResult rpe = relative_pose_error(est, ref);
    ASSERT_TRUE(rpe.status.ok);
    ASSERT_EQ(rpe.pairs.size(), 20u);
    EXPECT_NEAR(rpe.rotation.mean, pitch, 1e-12);  // the unsigned RPE cannot tell the two apart
    EXPECT_NEAR(rpe.mean_rotation_vector.x(), 0.0, 1e-12);
    EXPECT_NEAR(rpe.mean_rotation_vector.z(), 0.0, 1e-12);
    EXPECT_NEAR(rpe.mean_translation.norm(), 0.0, 1e-12);
    if (alternating) {
      EXPECT_NEAR(rpe.mean_rotation_vector.y(), 0.0, 1e-12);
      // SD of ±p over 20 pairs is p·√(20/19); its standard error that over √20.
      EXPECT_NEAR(rpe.rotation_vector_standard_error.y(), pitch / std::sqrt(19.0), 1e-12);
    } else {
      EXPECT_NEAR(rpe.mean_rotation_vector.y(), pitch, 1e-12);
      EXPECT_NEAR(rpe.rotation_vector_standard_error.y(), 0.0, 1e-12);
    }
  }
}

// Every motion 0.5 % short along a path that turns: the scale error is −0.5 % with no spread. Steps
// ±1 % in turn: no scale error, a standard error of 1 %·√(20/19)/√20. Standing still (motions under
// kScaleMinMotion) has no direction: no pairs.
TEST(Rpe, ScaleErrorIsTheMotionsShortfallAlongTheReference) {
  const double turn = 10.0 * std::acos(-1.0) / 180.0;
  for (const bool alternating : {false, true}) {
    const Eigen::AngleAxisd yaw(turn, Eigen::Vector3d::UnitZ());
    // 2 m, not along an axis of the pose (a sideways-mounted scanner)
    const PoseList ref = chained(21, [&](int) { return at(1.2, 1.6) * yaw; });
    const PoseList est = chained(21, [&](int i) {
      const double scale = alternating ? (i % 2 == 0 ? 1.01 : 0.99) : 0.995;
      return at(1.2 * scale, 1.6 * scale) * yaw;
    });
    const RpeResult rpe = relative_pose_error(est, ref);
    ASSERT_TRUE(rpe.status.ok);
    EXPECT_EQ(rpe.scale_pairs, 20u);
    if (alternating) {
      EXPECT_NEAR(rpe.scale_error, 0.0, 1e-12);
      EXPECT_NEAR(rpe.scale_standard_error, 0.01 * std::sqrt(20.0 / 19.0) / std::sqrt(20.0), 1e-12);
    } else {
      EXPECT_NEAR(rpe.scale_error, -0.005, 1e-12);
      EXPECT_NEAR(rpe.scale_standard_error, 0.0, 1e-12);
      EXPECT_NEAR(rpe.mean_translation.norm(), 0.01, 1e-12);  // split over the axes of E's frame
      EXPECT_GT(std::abs(rpe.mean_translation.y()), 0.005);
    }
  }
  const PoseList still(5, Eigen::Isometry3d::Identity());
  const RpeResult none = relative_pose_error(still, still);
  ASSERT_TRUE(none.status.ok);
  EXPECT_EQ(none.scale_pairs, 0u);
  EXPECT_TRUE(std::isnan(none.scale_error));
}

TEST(KittiDrift, ConstantScaleError) {
  // A straight 999 m line with 1 m spacing; the estimate is 2 % too long. The devkit's last frame
  // has dist > first + L, i.e. L + 1 steps later, so each segment's error is 0.02·(L + 1) / L.
  PoseList ref, est;
  for (int i = 0; i < 1000; ++i) {
    ref.push_back(at(i, 0));
    est.push_back(at(1.02 * i, 0));
  }
  const KittiDriftResult r = kitti_drift(est, ref);
  ASSERT_TRUE(r.status.ok) << r.status.message;
  ASSERT_EQ(r.per_length.size(), 8u);
  double weighted = 0.0;
  std::size_t total = 0;
  for (const KittiSegmentDrift& seg : r.per_length) {
    const auto L = static_cast<std::size_t>(seg.length);
    const std::size_t expected_count = (998 - L) / 10 + 1;  // first frames 0, 10, … ≤ 998 − L
    EXPECT_EQ(seg.segments, expected_count) << L;
    EXPECT_NEAR(seg.translation, 0.02 * (seg.length + 1) / seg.length, 1e-12) << L;
    EXPECT_NEAR(seg.rotation, 0.0, 1e-12);
    weighted += seg.translation * static_cast<double>(seg.segments);
    total += seg.segments;
  }
  EXPECT_EQ(r.segments, total);
  EXPECT_NEAR(r.translation, weighted / static_cast<double>(total), 1e-12);
  EXPECT_NEAR(r.translation, 0.02, 0.0002);

  PoseList short_ref(ref.begin(), ref.begin() + 50), short_est(est.begin(), est.begin() + 50);
  EXPECT_FALSE(kitti_drift(short_est, short_ref).status.ok);
}

TEST(TrajectoryMetrics, NonFiniteAndEmptyInputAreStatusNotCrash) {
  PoseList ref{at(0, 0), at(1, 0)};
  PoseList est = ref;
  est[1].translation().x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(wulf_metric(est, ref).status.ok);
  EXPECT_FALSE(kummerle_metric(est, ref).status.ok);
  EXPECT_FALSE(absolute_trajectory_error(est, ref).status.ok);
  EXPECT_FALSE(relative_pose_error(est, ref).status.ok);
  EXPECT_FALSE(kitti_drift(est, ref).status.ok);
  EXPECT_FALSE(wulf_metric({}, {}).status.ok);
  EXPECT_FALSE(absolute_trajectory_error({}, {}).status.ok);
}

}  // namespace
}  // namespace sextant

namespace sextant {
namespace {

// Brute force of evo's all-pairs path selection (argmin of |path − delta|, first on ties).
std::vector<std::pair<std::size_t, std::size_t>> brute_force_pairs(const PoseList& poses, double delta,
                                                                   double tol) {
  const std::vector<double> d = path_distances(poses);
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i + 1 < d.size(); ++i) {
    std::size_t best = i + 1;
    for (std::size_t j = i + 1; j < d.size(); ++j)
      if (std::abs(d[j] - d[i] - delta) < std::abs(d[best] - d[i] - delta)) best = j;
    if (std::abs(d[best] - d[i] - delta) <= tol) pairs.emplace_back(i, best);
  }
  return pairs;
}

TEST(Rpe, AllPairsByPathMatchesBruteForceOnStopAndGo) {
  Rng rng(3);
  PoseList poses;
  double x = 0.0;
  for (int i = 0; i < 300; ++i) {
    if (rng.uniform() < 0.4) x += rng.uniform(0.0, 1.5);  // stops repeat the distance
    poses.push_back(at(x, 0.0));
  }
  RpeSettings s;
  s.unit = RpeSettings::Unit::meters;
  s.all_pairs = true;
  for (double delta : {0.5, 3.0, 10.0}) {
    s.delta = delta;
    s.tolerance = 0.3;
    EXPECT_EQ(rpe_pairs(poses, s), brute_force_pairs(poses, delta, 0.3)) << delta;
  }
}

}  // namespace
}  // namespace sextant
