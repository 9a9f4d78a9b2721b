// Precision and recall of loop-closure candidates against a trajectory's true revisits.
#include <gtest/gtest.h>

#include <cmath>

#include "sextant/eval/loop_detection_metrics.hpp"

namespace sextant {
namespace {

/// 0 … 59 along x (1 m apart), then 60 … 79 back over x = 0 … 19.
PoseList out_and_back() {
  PoseList truth;
  for (int k = 0; k < 60; ++k) truth.push_back(Eigen::Isometry3d(Eigen::Translation3d(k, 0, 0)));
  for (int k = 0; k < 20; ++k) truth.push_back(Eigen::Isometry3d(Eigen::Translation3d(k, 0.5, 0)));
  return truth;
}

TEST(LoopDetectionMetrics, RevisitingScansAreThoseBackNearAnEarlierOne) {
  RevisitSettings s;
  s.radius = 1.0;
  s.min_index_gap = 30;
  const std::vector<bool> r = revisiting_scans(out_and_back(), s);
  for (std::size_t j = 0; j < 60; ++j) EXPECT_FALSE(r[j]) << j;  // 30 … 59 are new ground
  for (std::size_t j = 60; j < 80; ++j) EXPECT_TRUE(r[j]) << j;
}

TEST(LoopDetectionMetrics, FalseClosuresJoinPlacesTrulyFartherApartThanTheRadius) {
  // 60 → 0 is 0.5 m apart (right), 75 → 40 is 25 m apart (wrong), 45 → 50 is 5 m apart: wrong at a
  // 1 m radius, right at 10 m (the index gap is not this function's business); 5 → 90 is outside.
  const PoseList truth = out_and_back();
  const std::vector<std::pair<std::size_t, std::size_t>> accepted{{0, 60}, {40, 75}, {45, 50}, {5, 90}};
  EXPECT_EQ(count_false_closures(accepted, truth, 1.0), 2u);
  EXPECT_EQ(count_false_closures(accepted, truth, 10.0), 1u);
  EXPECT_EQ(count_false_closures({}, truth, 1.0), 0u);
}

TEST(LoopDetectionMetrics, PrecisionAndRecallCountWhatTheyShould) {
  RevisitSettings s;
  s.radius = 1.0;
  s.tolerance = 4;
  // Two right candidates (60 → 0 finds 60 … 63, 70 → 10 finds 67 … 73), one wrong (75 → 40),
  // one too close in the sequence to be a revisit (50 → 45).
  const LoopDetectionScore score =
      score_loop_candidates({{0, 60}, {10, 70}, {40, 75}, {45, 50}}, out_and_back(), s);
  EXPECT_EQ(score.candidates, 4u);
  EXPECT_EQ(score.true_candidates, 2u);
  EXPECT_DOUBLE_EQ(score.precision, 0.5);
  EXPECT_EQ(score.revisiting_scans, 20u);
  EXPECT_EQ(score.found_scans, 4u + 7u);
  EXPECT_DOUBLE_EQ(score.recall, 11.0 / 20.0);
}

TEST(LoopDetectionMetrics, NothingToScoreIsNaN) {
  const LoopDetectionScore none = score_loop_candidates({}, out_and_back(), RevisitSettings{});
  EXPECT_TRUE(std::isnan(none.precision));
  EXPECT_EQ(none.recall, 0.0);
  PoseList straight;
  for (int k = 0; k < 50; ++k) straight.push_back(Eigen::Isometry3d(Eigen::Translation3d(k, 0, 0)));
  EXPECT_TRUE(std::isnan(score_loop_candidates({}, straight, RevisitSettings{}).recall));
}

}  // namespace
}  // namespace sextant
