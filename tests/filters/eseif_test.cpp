// ESEIF (Walter, Eustice, Leonard 2007): exact sparsity by relocalization, conservative against
// the exact filter, and a working plane SLAM. Exactness with the bound never reached is in
// linear_gaussian_test.cpp (every filter against the exact KF); faults in numerical_faults_test.cpp.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "plane_world.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/filters/eseif.hpp"
#include "sextant/filters/range_bearing_model.hpp"
#include "sextant/filters/yaml.hpp"
#include "sextant_test/random_draws.hpp"

namespace sextant {
namespace {

std::shared_ptr<LinearSlamModel> linear_model() {
  const Eigen::MatrixXd A = (Eigen::MatrixXd(2, 2) << 1.0, 0.1, -0.05, 0.95).finished();
  const Eigen::MatrixXd B = (Eigen::MatrixXd(2, 2) << 1.0, 0.0, 0.2, 1.0).finished();
  const Eigen::MatrixXd C = (Eigen::MatrixXd(2, 2) << 1.0, 0.0, 0.3, 1.0).finished();
  return std::make_shared<LinearSlamModel>(A, B, C);
}

double min_eigenvalue(const Eigen::MatrixXd& M) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (M + M.transpose())).eigenvalues().minCoeff();
}

// On a linear-Gaussian problem with 8 landmarks and the bound at 3: after relocalization the
// pose is linked to ≤ 3 landmarks, and Σ_eseif − Σ_exact is positive semidefinite at every step
// (the paper's consistency property; the EIF is the exact filter here, linear_gaussian_test.cpp).
TEST(Eseif, RelocalizationIsExactlySparseAndConservativeOnALinearProblem) {
  const auto model = linear_model();
  const Eigen::MatrixXd Q = (Eigen::MatrixXd(2, 2) << 0.04, 0.01, 0.01, 0.09).finished();
  const Eigen::MatrixXd R = (Eigen::MatrixXd(2, 2) << 0.25, -0.05, -0.05, 0.16).finished();
  EseifSettings s;
  s.max_active_landmarks = 3;
  s.relocation_landmarks = 1;
  s.mean_recovery = "exact";
  Eseif eseif("eseif", model, s);
  auto exact = make_filter("eif", model);
  const Eigen::Vector2d x0(1.0, -1.0);
  const Eigen::Matrix2d P0 = (Eigen::Matrix2d() << 0.5, 0.1, 0.1, 0.3).finished();
  ASSERT_TRUE(eseif.initialize(x0, P0).ok());
  ASSERT_TRUE(exact->initialize(x0, P0).ok());
  Rng rng(5);
  auto vec = [&rng](double scale) { return test::normal_draws<2>(rng, scale); };
  double worst = 0.0;
  const auto check = [&] {
    const Eigen::MatrixXd diff = eseif.covariance() - exact->covariance();
    worst = std::min(worst, min_eigenvalue(diff) / exact->covariance().norm());
  };
  for (int k = 0; k < 8; ++k) {
    const Eigen::VectorXd z = vec(5.0);
    ASSERT_TRUE(eseif.augment(z, R).ok());
    ASSERT_TRUE(exact->augment(z, R).ok());
  }
  check();
  for (int step = 0; step < 30; ++step) {
    const Eigen::VectorXd u = vec(1.0);
    ASSERT_TRUE(eseif.predict(u, Q).ok());
    ASSERT_TRUE(exact->predict(u, Q).ok());
    check();
    if (eseif.relocations() > 0) {
      EXPECT_LE(eseif.information().neighbours(0).size(), 3u) << step;
    }
    std::vector<int> ids;
    std::vector<Eigen::VectorXd> zs;
    for (int j = 0; j < 3; ++j) {
      ids.push_back((2 * step + j) % 8);
      zs.push_back(vec(1.0));
    }
    ASSERT_TRUE(eseif.update(zs, R, ids).ok());
    ASSERT_TRUE(exact->update(zs, R, ids).ok());
    check();
  }
  EXPECT_GT(eseif.relocations(), 5u);
  EXPECT_EQ(eseif.skipped_relocations(), 0u);
  EXPECT_GT(worst, -1e-9) << "Σ_eseif − Σ_exact has a negative eigenvalue";
  // Conservative, not vacuous: the pose variance is larger, but within a small factor.
  const double ratio = eseif.covariance()(0, 0) / exact->covariance()(0, 0);
  std::printf("[eseif] linear: %zu relocations, min eig(Σ_eseif − Σ_exact)/‖Σ‖ = %.2e, pose var ratio %.3f\n",
              eseif.relocations(), worst, ratio);
  EXPECT_GE(ratio, 1.0 - 1e-9);
  EXPECT_LT(ratio, 10.0);
}

TEST(Eseif, PlaneSlamKeepsThePoseLinkedToAtMostTheBoundAndLocalises) {
  const test::PlaneWorld world = test::make_plane_world(30, 2);
  auto model = std::make_shared<PlaneSlamModel>();
  EseifSettings s;
  s.max_active_landmarks = 4;
  s.relocation_landmarks = 3;
  Eseif eseif("eseif", model, s);
  auto known = test::start_plane_slam(eseif, world);
  std::size_t worst_links = 0;
  for (const SlamStepInput& step : world.steps) {
    ASSERT_TRUE(eseif.predict(step.u, world.Q).ok());
    if (eseif.relocations() > 0)
      worst_links = std::max(worst_links, eseif.information().neighbours(0).size());
    std::vector<Eigen::VectorXd> zs;
    std::vector<int> ids;
    for (const SlamObservation& o : step.observations) {
      zs.push_back(o.z);
      ids.push_back(known.at(o.landmark));
    }
    ASSERT_TRUE(eseif.update(zs, world.R, ids).ok());
  }
  EXPECT_GT(eseif.relocations(), 10u);
  EXPECT_LE(worst_links, 4u);
  EXPECT_EQ(eseif.summary().failures(), 0u);
  const double error = test::position_error(eseif.pose(), world.truth.back());
  const double odometry = test::position_error(world.odometry.back().vector(), world.truth.back());
  const Eigen::MatrixXd P = eseif.joint_covariance({});
  ASSERT_TRUE(P.allFinite());
  Eigen::VectorXd e = eseif.pose() - world.truth.back().vector();
  wrap_entries(e, model->pose_angles());
  const double nees = e.dot(P.llt().solve(e));
  std::printf("[eseif] planes, bound 4: %zu relocations, final error %.3f m (odometry %.3f m), NEES %.2f\n",
              eseif.relocations(), error, odometry, nees);
  EXPECT_LT(error, 0.5 * odometry);
  EXPECT_LT(nees, 22.46);  // χ²₆ at 99.9 %
}

TEST(Eseif, JointCovarianceIsTheExactMarginalOfItsInformationMatrix) {
  auto model = std::make_shared<PlaneSlamModel>();
  Eseif eseif("eseif", model, {});
  test::grow_random_plane_map(eseif, 12, 4);
  const Eigen::MatrixXd full = eseif.covariance();
  const Eigen::MatrixXd joint = eseif.joint_covariance({3, 7});
  Eigen::MatrixXd expected(14, 14);
  const std::vector<Eigen::Index> rows{0, 1, 2, 3, 4, 5, 18, 19, 20, 21, 34, 35, 36, 37};
  for (int a = 0; a < 14; ++a)
    for (int b = 0; b < 14; ++b) expected(a, b) = full(rows[a], rows[b]);
  EXPECT_LT((joint - expected).norm(), 1e-9 * expected.norm());
  EXPECT_THROW(eseif.joint_covariance({12}), std::out_of_range);
}

TEST(Eseif, SettingsAreChecked) {
  std::string why;
  EseifSettings s;
  s.relocation_landmarks = 0;
  EXPECT_FALSE(s.valid(&why));
  s = {};
  s.relocation_prior = {1.0, -1.0};
  EXPECT_FALSE(s.valid(&why));
  s = {};
  s.mean_recovery = "magic";
  EXPECT_FALSE(s.valid(&why));
  s = {};
  s.relocation_prior = {1.0, 1.0};
  EXPECT_THROW(Eseif("eseif", std::make_shared<PlaneSlamModel>(), s), std::invalid_argument);
}

}  // namespace
}  // namespace sextant
