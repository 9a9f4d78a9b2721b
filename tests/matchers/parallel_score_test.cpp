// Parallel score accumulation (issue 4, "Performance"): the input is summed in fixed blocks of
// kScoreBlockPoints points whose sums are added in block order, so score, gradient and Hessian —
// and with them whole registrations — are bit-identical for every thread count. Checked with
// EXPECT_EQ on doubles, not NEAR, on the fast_gicp Velodyne pair (69,088 points: 34 blocks).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <limits>
#include <string>
#include <vector>

#include "ndt/ndt_score.hpp"
#include "pose_errors.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/ndt_matcher.hpp"
#include "sextant/matchers/yaml.hpp"
#include "test_clouds.hpp"

namespace sextant {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const std::vector<int> kThreadCounts = {1, 2, 3, 8, 0};  // 0: all hardware threads

struct VelodyneScans {
  PointCloud ref, in;
  Eigen::Isometry3d truth;  ///< p_ref = truth · p_in
  VelodyneScans() {
    const std::string dir = std::string(SEXTANT_DATA_DIR) + "/velodyne_pair/";
    ref = read_cloud(dir + "fast_gicp_251370668.pcd");
    in = read_cloud(dir + "fast_gicp_251371071.pcd");
    truth = test::read_transform(dir + "fast_gicp_relative.txt");
  }
};

const VelodyneScans& velodyne() {
  static const VelodyneScans pair;
  return pair;
}

/// Layers 1..6 of the reference (the outdoor settings of real_pairs_test.cpp).
const std::vector<NdtGrid>& velodyne_layers() {
  static const std::vector<NdtGrid> layers = [] {
    LayerPyramidSettings settings;
    settings.bounds_quantile = 0.0;  // the bounding box: dense enough cells at n = 6 for the checks below
    settings.layers = 6;
    return build_layer_pyramid(velodyne().ref, settings);
  }();
  return layers;
}

/// Near the true pose, not at it: most points match, some fall beyond a truncation.
Vector6d near_truth() {
  Vector6d xi = to_pose6(velodyne().truth).vector();
  Vector6d offset;
  offset << 0.08, -0.05, 0.02, 0.004, -0.003, 0.01;
  return xi + offset;
}

void expect_identical(const ScoreEvaluation& a, const ScoreEvaluation& b, const std::string& what) {
  EXPECT_EQ(a.score, b.score) << what;
  EXPECT_EQ(a.matched, b.matched) << what;
  EXPECT_EQ(a.rejected, b.rejected) << what;
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(a.gradient(i), b.gradient(i)) << what << " gradient " << i;
    for (int j = 0; j < 6; ++j) {
      EXPECT_EQ(a.hessian(i, j), b.hessian(i, j)) << what << " hessian " << i << "," << j;
      EXPECT_EQ(a.gauss_newton(i, j), b.gauss_newton(i, j)) << what << " gauss_newton " << i << "," << j;
    }
  }
}

void expect_identical(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, const std::string& what) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      EXPECT_EQ(a.matrix()(r, c), b.matrix()(r, c)) << what << " T(" << r << "," << c << ")";
}

TEST(ParallelScore, VelodyneInputSpansManyBlocks) {
  EXPECT_GT(velodyne().in.size(), 16 * kScoreBlockPoints);
  EXPECT_NE(velodyne().in.size() % kScoreBlockPoints, 0u);  // a short last block too
}

TEST(ParallelScore, MahalanobisIsBitIdenticalForEveryThreadCount) {
  const PointCloud& input = velodyne().in;
  const Vector6d xi = near_truth();
  for (const int layer : {4, 6}) {
    const NdtGrid& grid = velodyne_layers()[static_cast<std::size_t>(layer - 1)];
    for (const double tau : {kInf, 16.0}) {
      for (const Derivatives d : {Derivatives::kScore, Derivatives::kGradient, Derivatives::kHessian}) {
        const ScoreEvaluation one = mahalanobis_score(grid, input, xi, d, tau, ScoreThreads(1));
        ASSERT_GT(one.matched, input.size() / 2);
        if (tau < kInf) {
          EXPECT_GT(one.rejected, 0u);
        }
        for (const int threads : kThreadCounts) {
          const ScoreEvaluation many = mahalanobis_score(grid, input, xi, d, tau, ScoreThreads(threads));
          expect_identical(one, many,
                           "layer " + std::to_string(layer) + ", tau " + std::to_string(tau) +
                               ", derivatives " + std::to_string(static_cast<int>(d)) + ", threads " +
                               std::to_string(threads));
        }
      }
    }
  }
}

TEST(ParallelScore, GaussianIsBitIdenticalForEveryThreadCount) {
  const PointCloud& input = velodyne().in;
  const Vector6d xi = near_truth();
  const NdtGrid grid = NdtGrid::build_over_bounds(velodyne().ref, 1.0);
  const GaussianScoreParams p = GaussianScoreParams::from_outlier_ratio(0.55, 1.0);
  for (const bool trilinear : {false, true}) {
    for (const Derivatives d : {Derivatives::kScore, Derivatives::kHessian}) {
      const ScoreEvaluation one = gaussian_score(grid, input, xi, p, trilinear, d, ScoreThreads(1));
      ASSERT_GT(one.matched, input.size() / 2);
      for (const int threads : kThreadCounts) {
        const ScoreEvaluation many = gaussian_score(grid, input, xi, p, trilinear, d, ScoreThreads(threads));
        expect_identical(one, many,
                         std::string(trilinear ? "trilinear" : "nearest") + ", derivatives " +
                             std::to_string(static_cast<int>(d)) + ", threads " + std::to_string(threads));
      }
    }
  }
}

// The documented order: each block of kScoreBlockPoints points summed from zero, the block sums
// added from the first block on (which is what a smaller input's evaluation gives per block).
TEST(ParallelScore, ScoreIsTheSumOfBlockScoresInBlockOrder) {
  const PointCloud& input = velodyne().in;
  const NdtGrid& grid = velodyne_layers()[5];
  const Vector6d xi = near_truth();
  double score = 0.0;
  std::size_t matched = 0;
  for (std::size_t begin = 0; begin < input.size(); begin += kScoreBlockPoints) {
    std::vector<std::size_t> indices;
    for (std::size_t i = begin; i < std::min(input.size(), begin + kScoreBlockPoints); ++i)
      indices.push_back(i);
    const ScoreEvaluation block =
        mahalanobis_score(grid, input.subset(indices), xi, Derivatives::kScore, kInf);
    score += block.score;
    matched += block.matched;
  }
  for (const int threads : {1, 2}) {
    const ScoreEvaluation all =
        mahalanobis_score(grid, input, xi, Derivatives::kScore, kInf, ScoreThreads(threads));
    EXPECT_EQ(all.score, score) << threads;
    EXPECT_EQ(all.matched, matched) << threads;
  }
}

TEST(ParallelScore, SmallAndEmptyInputs) {
  const NdtGrid& grid = velodyne_layers()[5];
  const Vector6d xi = near_truth();
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, kScoreBlockPoints, kScoreBlockPoints + 1}) {
    std::vector<std::size_t> indices;
    for (std::size_t i = 0; i < n; ++i) indices.push_back(i);
    const PointCloud input = velodyne().in.subset(indices);
    const ScoreEvaluation one =
        mahalanobis_score(grid, input, xi, Derivatives::kHessian, kInf, ScoreThreads(1));
    for (const int threads : kThreadCounts)
      expect_identical(one,
                       mahalanobis_score(grid, input, xi, Derivatives::kHessian, kInf, ScoreThreads(threads)),
                       std::to_string(n) + " points, threads " + std::to_string(threads));
  }
}

TEST(ParallelScore, ThreadsAreCappedAndEveryBlockRunsOnce) {
  EXPECT_EQ(ScoreThreads().concurrency(), 1);
  EXPECT_EQ(ScoreThreads(1).concurrency(), 1);
  EXPECT_GE(ScoreThreads(0).concurrency(), 1);
  EXPECT_GE(ScoreThreads(2).concurrency(), 1);
  EXPECT_LE(ScoreThreads(2).concurrency(), 2);
  EXPECT_EQ(ScoreThreads(1000).concurrency(), ScoreThreads(0).concurrency());
  for (const int threads : kThreadCounts) {
    const ScoreThreads pool(threads);
    for (int round = 0; round < 3; ++round) {  // the arena is reused
      std::vector<int> runs(37, 0);
      pool.for_each(runs.size(), [&](std::size_t i) { ++runs[i]; });
      EXPECT_EQ(runs, std::vector<int>(37, 1)) << threads;
    }
  }
}

// One ScoreThreads for many evaluations (as a registration does) changes nothing either.
TEST(ParallelScore, ReusedThreadsGiveTheSameEvaluations) {
  const PointCloud& input = velodyne().in;
  const NdtGrid& grid = velodyne_layers()[5];
  const ScoreThreads pool(2);
  Vector6d xi = near_truth();
  for (int step = 0; step < 5; ++step) {
    xi(5) += 0.001;
    expect_identical(mahalanobis_score(grid, input, xi, Derivatives::kHessian, 16.0),
                     mahalanobis_score(grid, input, xi, Derivatives::kHessian, 16.0, pool),
                     "step " + std::to_string(step));
  }
}

TEST(ParallelScore, MlndtRegistrationIsBitIdenticalForOneAndFourThreads) {
  const VelodyneScans& p = velodyne();
  std::vector<RegistrationResult> results;
  for (const int threads : {1, 4}) {
    auto matcher = make_matcher(
        "mlndt",
        YAML::Load("{layers: 6, max_distance: 16, unmatched_penalty: 16, bounds_quantile: 0, threads: " +
                   std::to_string(threads) + "}"));
    matcher->set_reference(p.ref);
    results.push_back(matcher->align(p.in, Eigen::Isometry3d::Identity()));
  }
  ASSERT_TRUE(results[0].converged) << results[0].summary();
  EXPECT_GT(results[0].iterations, 3);
  expect_identical(results[0].T, results[1].T, "mlndt");
  EXPECT_EQ(results[0].iterations, results[1].iterations);
  EXPECT_EQ(results[0].score, results[1].score);
  EXPECT_EQ(results[0].matched_points, results[1].matched_points);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) EXPECT_EQ(results[0].H(i, j), results[1].H(i, j)) << i << "," << j;
}

// The parts that run side by side when a registration has threads — the pyramid beside the precision
// grids, the wide basin's hypotheses and its starts, refine_first's two runs and the precision
// stage's two grids — give the same model and the same bits as one thread, from a guess the wide
// basin has to correct (0.8 m and 8° off).
TEST(ParallelScore, WideBasinRegistrationIsBitIdenticalForOneAndTwoThreads) {
  const VelodyneScans& p = velodyne();
  const Eigen::Isometry3d guess = p.truth * to_isometry(Pose6{0.8, -0.5, 0.0, 0.0, 0.0, 0.14});
  std::vector<RegistrationResult> results;
  std::vector<std::vector<std::size_t>> modelled;
  for (const int threads : {1, 2}) {
    MlndtSettings settings;
    settings.wide_basin.enabled = true;
    settings.threads = threads;
    MlndtMatcher matcher(settings);
    matcher.set_reference(p.ref);
    modelled.emplace_back();
    for (const NdtGrid& g : matcher.layers()) modelled.back().push_back(g.modelled_points());
    for (const NdtGrid& g : matcher.precision_layers()) modelled.back().push_back(g.modelled_points());
    results.push_back(matcher.align(p.in, guess));
  }
  ASSERT_EQ(modelled[0].size(), 4u + 2u) << "four layers and the precision stage's two grids";
  EXPECT_EQ(modelled[0], modelled[1]);
  ASSERT_TRUE(results[0].converged) << results[0].summary();
  EXPECT_LT((results[0].T.translation() - p.truth.translation()).norm(), 0.1) << "the wide basin recovers";
  expect_identical(results[0].T, results[1].T, "wide basin");
  EXPECT_EQ(results[0].iterations, results[1].iterations);
  EXPECT_EQ(results[0].score, results[1].score);
  EXPECT_EQ(results[0].matched_points, results[1].matched_points);
}

// The whole registration with `threads: 0` (all TBB allows) under a process-wide TBB limit of one
// and of two threads (tbb::global_control), with the library's default preset: the same bits.
TEST(ParallelScore, MlndtRegistrationIsBitIdenticalUnderTbbLimitsOneAndTwo) {
  const VelodyneScans& p = velodyne();
  std::vector<RegistrationResult> results;
  std::vector<int> concurrency;
  for (const std::size_t limit : {std::size_t{1}, std::size_t{2}}) {
    const tbb::global_control control(tbb::global_control::max_allowed_parallelism, limit);
    concurrency.push_back(ScoreThreads(0).concurrency());
    auto matcher = make_matcher("mlndt", YAML::Load("{preset: default, threads: 0}"));
    matcher->set_reference(p.ref);
    results.push_back(matcher->align(p.in, Eigen::Isometry3d::Identity()));
  }
  EXPECT_EQ(concurrency[0], 1);
  ASSERT_TRUE(results[0].converged) << results[0].summary();
  expect_identical(results[0].T, results[1].T, "mlndt under TBB limits 1 and 2");
  EXPECT_EQ(results[0].iterations, results[1].iterations);
  EXPECT_EQ(results[0].score, results[1].score);
  EXPECT_EQ(results[0].matched_points, results[1].matched_points);
}

TEST(ParallelScore, NdtRegistrationIsBitIdenticalForOneAndTwoThreads) {
  Rng rng(1), rng2(2);
  const PointCloud reference = test::yard(rng, 2);
  const PointCloud input =
      test::yard(rng2, 2).transformed(to_isometry(Pose6{0.4, -0.3, 0.0, 0.0, 0.0, 0.03}));
  std::vector<RegistrationResult> results;
  for (const int threads : {1, 2}) {
    auto matcher = make_matcher(
        "ndt", YAML::Load("{cell_size: 2.0, trilinear: true, threads: " + std::to_string(threads) + "}"));
    matcher->set_reference(reference);
    results.push_back(matcher->align(input, Eigen::Isometry3d::Identity()));
  }
  ASSERT_TRUE(results[0].converged) << results[0].summary();
  expect_identical(results[0].T, results[1].T, "ndt");
  EXPECT_EQ(results[0].iterations, results[1].iterations);
  EXPECT_EQ(results[0].score, results[1].score);
}

TEST(ParallelScore, ThreadsSettingIsReadAndValidated) {
  for (const char* method : {"mlndt", "ndt"}) {
    EXPECT_NO_THROW(make_matcher(method, YAML::Load("{threads: 0}"))) << method;
    EXPECT_NO_THROW(make_matcher(method, YAML::Load("{threads: 3}"))) << method;
    try {
      make_matcher(method, YAML::Load("{threads: -1}"), "s.yaml");
      ADD_FAILURE() << method << ": expected InputError";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("threads"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("s.yaml"), std::string::npos) << e.what();
    }
    EXPECT_THROW(make_matcher(method, YAML::Load("{threads: two}")), InputError) << method;
  }
  MlndtSettings mlndt;
  EXPECT_EQ(mlndt.threads, 1);
  mlndt.threads = -2;
  std::string why;
  EXPECT_FALSE(mlndt.valid(&why));
  EXPECT_NE(why.find("threads"), std::string::npos) << why;
  NdtSettings ndt;
  EXPECT_EQ(ndt.threads, 1);
  ndt.threads = -1;
  EXPECT_FALSE(ndt.valid(&why));
}

}  // namespace
}  // namespace sextant
