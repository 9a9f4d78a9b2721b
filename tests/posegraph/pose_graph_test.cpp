// The pose graph on known answers: a square loop with noisy odometry and an exact closure comes
// back near the truth; a false closure is harmless with the robust loss and wrecks the map
// without it; the first pose (gauge) never moves; a singular information is a status, not NaN.
#include <cmath>

#include <gtest/gtest.h>

#include "sextant/core/rng.hpp"
#include "sextant/posegraph/pose_graph.hpp"

namespace sextant {
namespace {

/// A 20 m square driven anticlockwise, 10 poses a side, gently up and down hills; truth[0] ≠ I.
std::vector<Eigen::Isometry3d> square_truth() {
  std::vector<Eigen::Isometry3d> truth;
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < 10; ++k) {
      const double s = 2.0 * k, yaw = side * M_PI / 2;
      const Eigen::Vector2d corner[4] = {{0, 0}, {20, 0}, {20, 20}, {0, 20}};
      const Eigen::Vector2d p = corner[side] + s * Eigen::Vector2d(std::cos(yaw), std::sin(yaw));
      truth.push_back(to_isometry(
          {p.x() + 3.0, p.y() - 1.0, 0.3 * std::sin(0.2 * (10 * side + k)), 0.01, -0.02, yaw + 0.4}));
    }
  return truth;
}

Matrix6d diagonal_information(double sigma_t, double sigma_r) {
  Matrix6d omega = Matrix6d::Zero();
  omega.diagonal() << Eigen::Vector3d::Constant(1 / (sigma_t * sigma_t)),
      Eigen::Vector3d::Constant(1 / (sigma_r * sigma_r));
  return omega;
}

constexpr double kSigmaT = 0.05, kSigmaR = 0.02;

struct Loop {
  std::vector<Eigen::Isometry3d> truth, chained;
  PoseGraph graph;
};

/// Odometry = true step ⊕ N(0, σ) noise, chained from the true first pose; one exact closure
/// from the last pose to the first.
Loop make_loop(std::uint64_t seed) {
  Loop loop;
  loop.truth = square_truth();
  Rng rng(seed);
  loop.chained.push_back(loop.truth[0]);
  loop.graph.add_node(loop.truth[0]);
  for (std::size_t k = 1; k < loop.truth.size(); ++k) {
    const Eigen::Isometry3d noise =
        to_isometry({kSigmaT * rng.normal(), kSigmaT * rng.normal(), kSigmaT * rng.normal(),
                     kSigmaR * rng.normal(), kSigmaR * rng.normal(), kSigmaR * rng.normal()});
    const Eigen::Isometry3d step = relative(loop.truth[k - 1], loop.truth[k]) * noise;
    loop.chained.push_back(loop.chained.back() * step);
    loop.graph.add_node(loop.chained.back());
    loop.graph.add_edge(k - 1, k, step, diagonal_information(kSigmaT, kSigmaR), EdgeKind::odometry);
  }
  const std::size_t last = loop.truth.size() - 1;
  loop.graph.add_edge(last, 0, relative(loop.truth[last], loop.truth[0]), diagonal_information(0.01, 0.002),
                      EdgeKind::loop_closure);
  return loop;
}

double mean_position_error(const std::vector<Eigen::Isometry3d>& a, const std::vector<Eigen::Isometry3d>& b) {
  double sum = 0;
  for (std::size_t k = 0; k < a.size(); ++k) sum += (a[k].translation() - b[k].translation()).norm();
  return sum / static_cast<double>(a.size());
}

TEST(PoseGraph, SquareLoopWithAnExactClosureComesBackNearTheTruth) {
  for (std::uint64_t seed : {1, 2, 3}) {
    Loop loop = make_loop(seed);
    const PoseGraphReport r = loop.graph.optimize({});
    ASSERT_TRUE(r.ok) << r.message;
    EXPECT_EQ(r.nodes, 40u);
    EXPECT_EQ(r.odometry_edges, 39u);
    EXPECT_EQ(r.loop_closure_edges, 1u);
    EXPECT_GT(r.iterations, 0);
    EXPECT_LT(r.final_cost, r.initial_cost);
    const double chained = mean_position_error(loop.chained, loop.truth);
    const double optimised = mean_position_error(loop.graph.poses(), loop.truth);
    EXPECT_LT(optimised, 0.75 * chained) << "seed " << seed << ": chained " << chained;
    // Where the closure acts, the loop is closed: the last pose comes back to the truth.
    const double end_chained = (loop.chained.back().translation() - loop.truth.back().translation()).norm();
    const double end = (loop.graph.poses().back().translation() - loop.truth.back().translation()).norm();
    EXPECT_LT(end, 0.2 * end_chained) << "seed " << seed;
    // The closure ends close to its measurement: its error within a few σ.
    ASSERT_EQ(r.closure_chi2.size(), 1u);
    EXPECT_LT(r.closure_chi2[0], 30.0);
  }
}

TEST(PoseGraph, TheRobustLossKeepsAFalseClosureFromWreckingTheMap) {
  Loop clean = make_loop(5);
  ASSERT_TRUE(clean.graph.optimize({}).ok);
  const double clean_error = mean_position_error(clean.graph.poses(), clean.truth);
  // A false closure between opposite sides of the square (≈ 20 m apart) saying "same place".
  const auto with_false_closure = [](RobustLoss loss) {
    Loop loop = make_loop(5);
    loop.graph.add_edge(5, 25, Eigen::Isometry3d::Identity(), diagonal_information(0.01, 0.002),
                        EdgeKind::loop_closure);
    PoseGraphSettings s;
    s.loss = loss;
    const PoseGraphReport r = loop.graph.optimize(s);
    EXPECT_TRUE(r.ok) << r.message;
    EXPECT_EQ(r.closure_weights.size(), 2u);
    return std::make_pair(mean_position_error(loop.graph.poses(), loop.truth), r);
  };
  const auto [cauchy_error, cauchy] = with_false_closure(RobustLoss::cauchy);
  const auto [plain_error, plain] = with_false_closure(RobustLoss::none);
  EXPECT_LT(cauchy_error, clean_error + 0.05) << "clean " << clean_error;
  EXPECT_GT(plain_error, 5.0 * clean_error + 1.0) << "clean " << clean_error;
  // Cauchy down-weighted the false closure (index 1) and kept the true one (index 0).
  EXPECT_LT(cauchy.closure_weights[1], 0.01);
  EXPECT_GT(cauchy.closure_weights[0], 0.5);
  const auto [huber_error, huber] = with_false_closure(RobustLoss::huber);
  (void)huber;
  EXPECT_LT(huber_error, plain_error);
}

TEST(PoseGraph, TheFirstPoseIsTheGauge) {
  Loop loop = make_loop(7);
  // Pull hard on the first pose through a closure that disagrees with it.
  loop.graph.add_edge(0, 39, to_isometry({5, 5, 1, 0.1, 0.1, 0.5}), diagonal_information(0.01, 0.001),
                      EdgeKind::odometry);
  const Eigen::Isometry3d first = loop.graph.poses()[0];
  ASSERT_TRUE(loop.graph.optimize({}).ok);
  EXPECT_EQ((loop.graph.poses()[0].matrix() - first.matrix()).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT((loop.graph.poses()[39].translation() - loop.chained[39].translation()).norm(), 0.5);
}

TEST(PoseGraph, ASingularInformationIsReportedAndNothingTurnsNaN) {
  Loop loop = make_loop(9);
  Matrix6d singular = diagonal_information(0.1, 0.01);
  singular(4, 4) = 0.0;
  loop.graph.add_edge(3, 30, Eigen::Isometry3d::Identity(), singular, EdgeKind::loop_closure);
  const std::vector<Eigen::Isometry3d> before = loop.graph.poses();
  const PoseGraphReport r = loop.graph.optimize({});
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("edge 40 (3 → 30, loop closure)"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("information"), std::string::npos) << r.message;
  for (std::size_t k = 0; k < before.size(); ++k) {
    EXPECT_TRUE(is_finite(loop.graph.poses()[k]));
    EXPECT_EQ((loop.graph.poses()[k].matrix() - before[k].matrix()).norm(), 0.0);
  }
  PoseGraph nan_graph;
  nan_graph.add_node(Eigen::Isometry3d::Identity());
  nan_graph.add_node(Eigen::Isometry3d::Identity());
  Matrix6d nan = Matrix6d::Identity();
  nan(0, 0) = std::nan("");
  nan_graph.add_edge(0, 1, Eigen::Isometry3d::Identity(), nan, EdgeKind::odometry);
  EXPECT_FALSE(nan_graph.optimize({}).ok);
  PoseGraph bad_index;
  bad_index.add_node(Eigen::Isometry3d::Identity());
  bad_index.add_edge(0, 3, Eigen::Isometry3d::Identity(), Matrix6d::Identity(), EdgeKind::odometry);
  EXPECT_FALSE(bad_index.optimize({}).ok);
}

TEST(PoseGraph, RobustWeights) {
  EXPECT_DOUBLE_EQ(robust_weight(RobustLoss::none, 3.0, 1e6), 1.0);
  EXPECT_DOUBLE_EQ(robust_weight(RobustLoss::cauchy, 3.0, 9.0), 0.5);
  EXPECT_DOUBLE_EQ(robust_weight(RobustLoss::huber, 3.0, 4.0), 1.0);
  EXPECT_DOUBLE_EQ(robust_weight(RobustLoss::huber, 3.0, 36.0), 0.5);
  PoseGraphSettings bad;
  bad.loss_scale = -1;
  std::string why;
  EXPECT_FALSE(bad.valid(&why));
}

}  // namespace
}  // namespace sextant
