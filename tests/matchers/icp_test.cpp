#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "icp/icp_steps.hpp"
#include "icp/kd_tree.hpp"
#include "pose_errors.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/matchers/icp.hpp"
#include "sextant/matchers/yaml.hpp"
#include "sextant_test/random_draws.hpp"

namespace sextant {
namespace {

using test::pose;
using test::rotation_error;
using test::translation_error;

/// A small structured scene: sloped ground, two walls, a box and a pole, sampled at random.
PointCloud synthetic_scene(Rng& rng, std::size_t n, double noise = 0.005) {
  PointCloud cloud;
  cloud.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = rng.uniform(), a = rng.uniform(), b = rng.uniform();
    Eigen::Vector3d p;
    if (u < 0.4) {
      p = {a * 20.0 - 10.0, b * 20.0 - 10.0, 0.0};
      p.z() = 0.03 * p.x() + 0.02 * p.y();  // gentle slope
    } else if (u < 0.6) {
      p = {10.0, b * 20.0 - 10.0, a * 4.0};  // wall facing −x
    } else if (u < 0.8) {
      p = {a * 20.0 - 10.0, 10.0 - 0.1 * a, b * 3.0};  // slightly slanted wall
    } else if (u < 0.95) {
      const int face = static_cast<int>(rng.index(3));  // box at (2, −3)
      if (face == 0)
        p = {2.0, -3.0 + 2.0 * a, 1.5 * b};
      else if (face == 1)
        p = {2.0 + 1.5 * a, -3.0, 1.5 * b};
      else
        p = {2.0 + 1.5 * a, -3.0 + 2.0 * b, 1.5};
    } else {
      const double angle = 2.0 * M_PI * a;  // pole at (−4, 4)
      p = {-4.0 + 0.15 * std::cos(angle), 4.0 + 0.15 * std::sin(angle), 3.0 * b};
    }
    p += test::normal_draws<3>(rng, noise);
    cloud.push_back(p.cast<float>());
  }
  return cloud;
}

// ---------------------------------------------------------------- k-d tree

TEST(KdTree, NearestAndKNearestMatchBruteForce) {
  Rng rng(7);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 2000; ++i)
    points.push_back(test::uniform_draws<3>(rng, {-5, -5, -1}, {5, 5, 1}).cast<float>());
  points.emplace_back(NAN, 0.0f, 0.0f);  // skipped at build
  const KdTree tree(points, 4);
  EXPECT_EQ(tree.size(), 2000u);
  std::vector<KdTree::Neighbour> knn;
  for (int q = 0; q < 200; ++q) {
    const Eigen::Vector3f query = test::uniform_draws<3>(rng, {-6, -6, -2}, {6, 6, 2}).cast<float>();
    std::vector<std::pair<float, std::size_t>> brute;
    for (std::size_t i = 0; i < 2000; ++i) brute.emplace_back((points[i] - query).squaredNorm(), i);
    std::sort(brute.begin(), brute.end());
    KdTree::Neighbour n;
    ASSERT_TRUE(tree.nearest(query, &n));
    EXPECT_FLOAT_EQ(n.squared_distance, brute[0].first);
    tree.k_nearest(query, 7, knn);
    ASSERT_EQ(knn.size(), 7u);
    for (std::size_t k = 0; k < 7; ++k) EXPECT_FLOAT_EQ(knn[k].squared_distance, brute[k].first);
    // A radius below the nearest distance finds nothing.
    EXPECT_FALSE(tree.nearest(query, brute[0].first * 0.5f, &n));
  }
}

TEST(KdTree, EmptyAndNonFiniteQueriesFindNothing) {
  KdTree empty;
  KdTree::Neighbour n;
  EXPECT_FALSE(empty.nearest(Eigen::Vector3f::Zero(), &n));
  const KdTree tree(std::vector<Eigen::Vector3f>{Eigen::Vector3f::Zero(), Eigen::Vector3f::Ones()});
  EXPECT_FALSE(tree.nearest(Eigen::Vector3f(NAN, 0, 0), &n));
  std::vector<KdTree::Neighbour> knn;
  tree.k_nearest(Eigen::Vector3f::Zero(), 5, knn);
  EXPECT_EQ(knn.size(), 2u);
  ASSERT_TRUE(tree.nearest(Eigen::Vector3f(0.9f, 0.9f, 0.9f), &n));
  EXPECT_EQ(n.index, 1u);
}

// ---------------------------------------------------------------- single steps, exact data

TEST(IcpSteps, PointToPointRecoversExactTransformInOneStep) {
  Rng rng(3);
  const Eigen::Isometry3d truth = pose(0.4, -0.2, 0.1, 5, -3, 20);
  Correspondences pairs;
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector3d p = test::uniform_draws<3>(rng, {-5, -5, -2}, {5, 5, 2});
    pairs.input.push_back(p);
    pairs.reference.push_back(truth * p);
  }
  const IcpStep step = point_to_point_step(pairs);
  ASSERT_TRUE(step.ok) << step.problem;
  EXPECT_LT(translation_error(truth, step.delta), 1e-9);
  EXPECT_LT(rotation_error(truth, step.delta), 1e-9);
  EXPECT_LT(step.score_after, 1e-18);
  EXPECT_GT(step.score_before, 0.0);
}

TEST(IcpSteps, PointToPointRejectsCollinearPairs) {
  Correspondences pairs;
  for (int i = 0; i < 10; ++i) {
    pairs.input.emplace_back(i, 0, 0);
    pairs.reference.emplace_back(i, 0.1, 0);
  }
  const IcpStep step = point_to_point_step(pairs);
  EXPECT_FALSE(step.ok);
  EXPECT_FALSE(step.problem.empty());
}

TEST(IcpSteps, PointToPlaneSmallMotionConvergesQuadraticallyAndHasGaussNewtonH) {
  // Points on three orthogonal planes through the origin region; a small motion.
  Rng rng(5);
  const Eigen::Isometry3d truth = pose(0.02, -0.01, 0.015, 0.2, -0.1, 0.3);
  Correspondences pairs;
  const Eigen::Vector3d normals[3] = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                      Eigen::Vector3d::UnitZ()};
  for (int i = 0; i < 300; ++i) {
    Eigen::Vector3d q =
        test::uniform_draws<3>(rng, Eigen::Vector3d::Constant(-3), Eigen::Vector3d::Constant(3));
    const int k = i % 3;
    q[k] = 2.0 + k;  // plane x = 2, y = 3 or z = 4
    pairs.reference.push_back(q);
    pairs.normals.push_back(normals[k]);
    pairs.input.push_back(inverse(truth) * q);  // exact point-to-point pairs
  }
  const IcpStep step = point_to_plane_step(pairs);
  ASSERT_TRUE(step.ok) << step.problem;
  // One linearised step from ~1 cm / 0.3°: the residual error is second order.
  EXPECT_LT(translation_error(truth, step.delta), 1e-4);
  EXPECT_LT(rotation_error(truth, step.delta), 1e-4);
  EXPECT_LT(step.score_after, 1e-3 * step.score_before);
  // H = JᵀJ with J = [nᵀ, (p × n)ᵀ].
  Matrix6d H = Matrix6d::Zero();
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    Vector6d J;
    J << pairs.normals[i], pairs.input[i].cross(pairs.normals[i]);
    H += J * J.transpose();
  }
  EXPECT_LT((H - step.H).norm(), 1e-9 * H.norm());
}

TEST(IcpSteps, PointToPlaneRejectsParallelNormals) {
  Correspondences pairs;
  for (int i = 0; i < 20; ++i) {
    pairs.input.emplace_back(i, i % 5, 0.1);
    pairs.reference.emplace_back(i, i % 5, 0.0);
    pairs.normals.emplace_back(0, 0, 1);
  }
  const IcpStep step = point_to_plane_step(pairs);
  EXPECT_FALSE(step.ok);
}

// ---------------------------------------------------------------- whole registrations

class IcpSynthetic : public ::testing::TestWithParam<IcpObjective> {};

TEST_P(IcpSynthetic, RecoversKnownTransform) {
  Rng rng(11);
  const PointCloud reference = synthetic_scene(rng, 20000);
  const Eigen::Isometry3d truth = pose(0.5, -0.3, 0.05, 1.0, -1.5, 8.0);
  const PointCloud input = synthetic_scene(rng, 5000).transformed(inverse(truth));  // p_ref = T·p_in
  IcpSettings settings;
  settings.max_correspondence_distance = 2.0;
  settings.epsilon = 1e-6;
  settings.max_iterations = 100;
  const auto icp = make_icp(GetParam(), settings);
  icp->set_reference(reference);
  const RegistrationResult r = icp->align(input, Eigen::Isometry3d::Identity());
  EXPECT_TRUE(r.converged) << r.summary();
  EXPECT_LT(translation_error(truth, r.T), 0.01) << r.summary();
  EXPECT_LT(rotation_error(truth, r.T), 0.1 * kRadPerDeg) << r.summary();
  EXPECT_EQ(r.iterations, static_cast<int>(r.trace.size()));
  EXPECT_EQ(r.input_points, input.size());
  EXPECT_GT(r.matched_points, input.size() / 2);
  EXPECT_GT(r.H.trace(), 0.0);
  EXPECT_GE(r.seconds, 0.0);
}

TEST_P(IcpSynthetic, DegenerateInputNeverCrashes) {
  const auto icp = make_icp(GetParam(), IcpSettings{});
  PointCloud empty;
  // No reference yet.
  RegistrationResult r = icp->align(PointCloud(std::vector<Eigen::Vector3f>{Eigen::Vector3f::Zero()}),
                                    Eigen::Isometry3d::Identity());
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.why, Termination::kEmptyInput);

  // A flat plane: in-plane motion is not observable for point-to-plane; a line for both.
  Rng rng(2);
  PointCloud plane, line;
  for (int i = 0; i < 2000; ++i) {
    const double y = rng.uniform(-5, 5), x = rng.uniform(-5, 5);
    plane.push_back(Eigen::Vector3d(x, y, 0.0).cast<float>());
    line.push_back(Eigen::Vector3f(rng.uniform(-5, 5), 0.0f, 0.0f));
  }
  icp->set_reference(line);
  r = icp->align(line, pose(0.1, 0, 0, 0, 0, 0));
  EXPECT_FALSE(r.converged);
  EXPECT_TRUE(r.T.matrix().allFinite());

  icp->set_reference(plane);
  r = icp->align(empty, Eigen::Isometry3d::Identity());
  EXPECT_EQ(r.why, Termination::kEmptyInput);

  Eigen::Isometry3d nan_guess = Eigen::Isometry3d::Identity();
  nan_guess.translation().x() = NAN;
  r = icp->align(plane, nan_guess);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.why, Termination::kNonFiniteInput);
  EXPECT_TRUE(r.T.matrix().allFinite());

  // No overlap at all.
  r = icp->align(plane, pose(100, 0, 0, 0, 0, 0));
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.why, Termination::kTooFewCorrespondences);

  // NaN points in the input are skipped.
  PointCloud with_nan = plane;
  with_nan.push_back(Eigen::Vector3f(NAN, NAN, NAN));
  r = icp->align(with_nan, Eigen::Isometry3d::Identity());
  EXPECT_TRUE(r.T.matrix().allFinite());
  if (GetParam() == IcpObjective::kPointToPlane) {
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.why, Termination::kSolverFailure);
  }
}

INSTANTIATE_TEST_SUITE_P(Objectives, IcpSynthetic,
                         ::testing::Values(IcpObjective::kPointToPoint, IcpObjective::kPointToPlane),
                         [](const auto& info) {
                           return info.param == IcpObjective::kPointToPoint ? std::string("p2p")
                                                                            : std::string("p2l");
                         });

TEST_P(IcpSynthetic, DofMaskMovesOnlyTheFreeParameters) {
  // The thesis' 2D case: x, y and yaw free; z, roll and pitch keep their initial value (0).
  Rng rng(13);
  const PointCloud reference = synthetic_scene(rng, 20000);
  const Eigen::Isometry3d planar = pose(0.4, -0.3, 0.0, 0.0, 0.0, 5.0);
  const PointCloud input = synthetic_scene(rng, 5000).transformed(inverse(planar));
  IcpSettings settings;
  settings.max_correspondence_distance = 2.0;
  settings.epsilon = 1e-6;
  settings.max_iterations = 100;
  settings.dof.active = {true, true, false, false, false, true};
  const auto icp = make_icp(GetParam(), settings);
  icp->set_reference(reference);
  RegistrationResult r = icp->align(input, Eigen::Isometry3d::Identity());
  EXPECT_TRUE(r.converged) << r.summary();
  EXPECT_LT(translation_error(planar, r.T), 0.01) << r.summary();
  EXPECT_LT(rotation_error(planar, r.T), 0.1 * kRadPerDeg) << r.summary();
  const Pose6 p = to_pose6(r.T);
  EXPECT_NEAR(p.z, 0.0, 1e-12);
  EXPECT_NEAR(p.alpha, 0.0, 1e-12);
  EXPECT_NEAR(p.beta, 0.0, 1e-12);

  // A true height offset cannot be recovered with z fixed.
  const PointCloud lifted = synthetic_scene(rng, 5000).transformed(inverse(pose(0.4, -0.3, 0.3, 0, 0, 5.0)));
  r = icp->align(lifted, Eigen::Isometry3d::Identity());
  EXPECT_NEAR(to_pose6(r.T).z, 0.0, 1e-12);
}

TEST(IcpSettings, YamlErrorsNameTheKey) {
  const YAML::Node good = YAML::Load("max_correspondence_distance: 0.5\nnormal_neighbours: 12\n");
  EXPECT_EQ(read_icp_settings(IcpObjective::kPointToPlane, good, "s.yaml").normal_neighbours, 12);
  const IcpSettings planar =
      read_icp_settings(IcpObjective::kPointToPoint, YAML::Load("dof: [x, y, yaw]"), "s.yaml");
  EXPECT_EQ(planar.dof.count(), 3);
  EXPECT_FALSE(planar.dof.active[2]);
  EXPECT_THROW(read_icp_settings(IcpObjective::kPointToPoint, YAML::Load("dof: [x, up]"), "s.yaml"),
               InputError);
  // normal_neighbours means nothing to point-to-point.
  EXPECT_THROW(read_icp_settings(IcpObjective::kPointToPoint, good, "s.yaml"), InputError);
  try {
    read_icp_settings(IcpObjective::kPointToPoint, YAML::Load("epsilon: 1e-4\nmax_iterations: 0\n"),
                      "s.yaml");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "s.yaml");
    EXPECT_NE(std::string(e.what()).find("max_iterations"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_icp_settings(IcpObjective::kPointToPoint, YAML::Load("max_iterations: many"), "s.yaml"),
               InputError);
}

}  // namespace
}  // namespace sextant
