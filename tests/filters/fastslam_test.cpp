// FastSLAM 2.0 (fastslam.hpp) against known answers: the EKF formula for one landmark, the exact
// Kalman filter on a linear-Gaussian problem as N grows, resampling by N_eff, the shared map
// under resampling (copy counts, copy-on-write) and log weights under an impossible observation.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <cmath>
#include <cstdio>
#include <memory>

#include "exact_kalman.hpp"
#include "plane_world.hpp"
#include "sextant/filters/fastslam.hpp"
#include "sextant/filters/range_bearing_model.hpp"
#include "sextant_test/random_draws.hpp"

namespace sextant {
namespace {

std::shared_ptr<PlaneSlamModel> plane_model() {
  return std::make_shared<PlaneSlamModel>();
}

// With the pose known exactly (P0 = 0, no motion) one particle's landmark update is the EKF of
// eqs. (4.65)–(4.66) restricted to the landmark: K = Σ Hᵀ(H Σ Hᵀ + R)⁻¹, H = ∂h/∂m (eq. 4.65).
TEST(FastSlam, LandmarkUpdateOfOneParticleIsTheEkfFormula) {
  auto model = plane_model();
  FastSlam filter(model, {1, 0.5}, 3);
  Eigen::VectorXd pose(6);
  pose << 1.0, -2.0, 0.3, 0.02, -0.01, 0.7;
  ASSERT_TRUE(filter.initialize(pose, Eigen::MatrixXd::Zero(6, 6)).ok());
  const Eigen::Matrix4d R = Eigen::Vector4d(1e-4, 2e-4, 1e-4, 4e-2).asDiagonal();
  const Eigen::Vector4d z0 = test::plane(0.6, 0.8, 0.1, 7.0);
  ASSERT_TRUE(filter.augment(z0, R).ok());
  // The landmark after augmentation: g(s, z) and G_z R G_zᵀ (eqs. 4.57–4.58, 4.67).
  const LandmarkEkf start = filter.particles()[0].map.get(0);
  const Eigen::MatrixXd Gz = model->augment_jacobian_observation(pose, z0);
  EXPECT_LT((start.mean - model->augment(pose, z0)).norm(), 1e-12);
  EXPECT_LT((start.covariance - Gz * R * Gz.transpose()).norm(), 1e-15);

  const Eigen::Vector4d z1 = test::plane(0.62, 0.79, 0.09, 7.2);
  ASSERT_TRUE(filter.update({z1}, R, {0}).ok());
  const Eigen::MatrixXd H = model->observe_jacobian_landmark(pose, start.mean);
  const Eigen::MatrixXd S = H * start.covariance * H.transpose() + R;
  const Eigen::MatrixXd K = start.covariance * H.transpose() * S.inverse();
  Eigen::VectorXd expected = start.mean + K * (z1 - model->observe(pose, start.mean));
  model->normalize_landmark(expected);
  const Eigen::MatrixXd expected_cov = (Eigen::MatrixXd::Identity(4, 4) - K * H) * start.covariance;
  const LandmarkEkf& after = filter.particles()[0].map.get(0);
  EXPECT_LT((after.mean - expected).norm(), 1e-12);
  EXPECT_LT((after.covariance - expected_cov).norm(), 1e-12 * expected_cov.norm());
  EXPECT_LT((filter.particles()[0].pose - pose).norm(), 1e-15);  // Σ_s = 0: the pose stays
}

using test::linear_scenario;
using test::LinearScenario;

/// A draw from N(0, S).
Eigen::VectorXd noise(const Eigen::MatrixXd& S, Rng& rng) {
  Eigen::VectorXd xi(S.rows());
  for (Eigen::Index k = 0; k < xi.size(); ++k) xi[k] = rng.normal();
  return Eigen::LLT<Eigen::MatrixXd>(S).matrixL() * xi;
}

// Simulates the linear model (a true pose from the prior, 4 true landmarks, 8 steps of a noisy
// control and two noisy observations, the 4th landmark first seen at step 4) and runs FastSLAM
// with N particles and the exact KF on it; returns the difference at the end:
// ‖x − x_KF‖ / √tr P_KF + ‖P − P_KF‖ / ‖P_KF‖.
double end_difference(const LinearScenario& s, int particles, std::uint64_t seed) {
  FastSlam filter(s.model, {particles, 0.5}, seed);
  test::ExactKalman kf{s.A, s.B, s.C, s.x0, s.P0};
  EXPECT_TRUE(filter.initialize(s.x0, s.P0).ok());
  Rng rng(11);  // the same data for every N and seed
  Eigen::VectorXd pose = s.x0 + noise(s.P0, rng);
  std::vector<Eigen::VectorXd> landmarks;
  for (int k = 0; k < 4; ++k) landmarks.push_back(test::normal_draws<2>(rng) * 5.0);
  auto observe = [&](int k) { return (landmarks[k] - s.C * pose + noise(s.R, rng)).eval(); };
  auto augment = [&](int k) {
    const Eigen::VectorXd z = observe(k);
    EXPECT_TRUE(filter.augment(z, s.R).ok());
    kf.augment(z, s.R);
  };
  for (int k = 0; k < 3; ++k) augment(k);
  for (int step = 0; step < 8; ++step) {
    const Eigen::VectorXd u = test::normal_draws<2>(rng);
    pose = s.A * pose + s.B * (u + noise(s.Q, rng));
    EXPECT_TRUE(filter.predict(u, s.Q).ok());
    kf.predict(u, s.Q);
    const std::vector<int> ids{step % 3, (step + 1) % 3};
    const std::vector<Eigen::VectorXd> zs{observe(ids[0]), observe(ids[1])};
    EXPECT_TRUE(filter.update(zs, s.R, ids).ok());
    kf.update(zs, s.R, ids);
    if (step == 4) augment(3);
  }
  EXPECT_EQ(filter.summary().failures(), 0u);
  return (filter.mean() - kf.x).norm() / std::sqrt(kf.P.trace()) +
         (filter.covariance() - kf.P).norm() / kf.P.norm();
}

// In a linear-Gaussian model the FastSLAM 2.0 proposal is the optimal one and the particle
// mixture converges to the exact posterior: its mean and covariance approach the KF's as N grows
// (Monte-Carlo error ∝ 1/√N: 100× the particles, 1/10 the error).
TEST(FastSlam, LinearGaussianMomentsApproachTheExactKalmanFilterAsNGrows) {
  const LinearScenario s = linear_scenario();
  std::vector<double> error;
  for (int n : {20, 200, 2000}) {
    double sum = 0.0;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) sum += end_difference(s, n, seed) / 4.0;
    error.push_back(sum);
    std::printf("[fastslam-linear] N = %4d  mean relative difference to the exact KF %.4f\n", n, sum);
  }
  EXPECT_LT(error[1], error[0]);
  EXPECT_LT(error[2], error[1]);
  // Measured 0.94, 0.38, 0.094: the 1/√N of a correct Rao-Blackwellised filter.
  EXPECT_LT(error[2], 0.25 * error[0]);
  EXPECT_LT(error[2], 0.15);
}

// joint_covariance(ids) is the matching block of covariance().
TEST(FastSlam, JointCovarianceIsTheBlockOfTheMixtureCovariance) {
  const LinearScenario s = linear_scenario();
  FastSlam filter(s.model, {64, 0.5}, 2);
  ASSERT_TRUE(filter.initialize(s.x0, s.P0).ok());
  for (int k = 0; k < 3; ++k) ASSERT_TRUE(filter.augment(Eigen::Vector2d(k, 2.0 * k), s.R).ok());
  ASSERT_TRUE(filter.predict(Eigen::Vector2d(1.0, 0.5), s.Q).ok());
  ASSERT_TRUE(filter.update({Eigen::Vector2d(0.3, 1.0)}, s.R, {1}).ok());
  EXPECT_LT((filter.joint_covariance({2, 0}) - joint_block(*s.model, filter.covariance(), {2, 0})).norm(),
            1e-12);
  EXPECT_THROW(filter.joint_covariance({3}), std::out_of_range);
}

// Particles whose poses are spread around a landmark known exactly (each at its own pose, no
// motion: the proposal is the pose itself) weigh the observation x = 5 m by their own x. Spread
// by 3 mm against σ_d = 1 cm, the weights differ but N_eff stays above N/2: no resampling, the
// unequal weights are kept. Spread by 1 m, N_eff collapses and the set is resampled to equal
// weights.
TEST(FastSlam, ResamplesOnlyBelowTheEffectiveSampleSizeThreshold) {
  auto model = plane_model();
  const Eigen::Matrix4d R = Eigen::Vector4d(1e-4, 1e-4, 1e-4, 1e-4).asDiagonal();
  const Eigen::Vector4d z = test::plane(1, 0, 0, 5);
  const int n = 40;
  for (double sigma : {0.003, 1.0}) {
    FastSlam filter(model, {n, 0.5}, 7);
    Eigen::VectorXd diag(10);
    diag << sigma, sigma, sigma, 1e-5, 1e-5, 1e-5, 1e-6, 1e-6, 1e-6, 1e-6;
    ASSERT_TRUE(filter
                    .initialize((Eigen::VectorXd(10) << Eigen::VectorXd::Zero(6), z).finished(),
                                diag.array().square().matrix().asDiagonal())
                    .ok());
    ASSERT_TRUE(filter.update({z}, R, {0}).ok());
    const double n_eff = filter.effective_sample_size();
    std::printf(
        "[fastslam-resampling] pose spread %.3f m: N_eff %.2f of %d after weighting, resamplings %zu\n",
        sigma, filter.last_update_effective_sample_size(), n, filter.counters().resamplings);
    if (sigma < 0.01) {
      EXPECT_EQ(filter.counters().resamplings, 0u);
      EXPECT_GT(n_eff, 0.5 * n);
      EXPECT_LT(n_eff, n - 0.01);  // the weights differ: they were not reset by a resampling
    } else {
      EXPECT_EQ(filter.counters().resamplings, 1u);
      EXPECT_EQ(filter.counters().particle_copies, static_cast<std::size_t>(n));
      EXPECT_LT(filter.last_update_effective_sample_size(), 0.5 * n);
      EXPECT_NEAR(n_eff, n, 1e-9);  // uniform after resampling
    }
  }
}

}  // namespace
}  // namespace sextant
