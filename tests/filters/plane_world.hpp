#pragma once
// A small synthetic plane world for the SLAM tests: known planes, a true 6D trajectory, noisy
// (biased) odometry increments and noisy plane observations taken from the truth.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "sextant/core/rng.hpp"
#include "sextant/filters/plane_slam_model.hpp"
#include "sextant/filters/slam_runner.hpp"
#include "sextant_test/random_draws.hpp"

namespace sextant::test {

struct PlaneWorld {
  std::vector<Eigen::Vector4d> planes;
  std::vector<Pose6> truth;          ///< truth[0] is the start
  std::vector<SlamStepInput> steps;  ///< step k moves truth[k] → truth[k+1] and observes there
  std::vector<Eigen::VectorXd> first_observations;  ///< observations at truth[0]
  Eigen::MatrixXd Q, R;
  std::vector<Pose6> odometry;  ///< dead reckoning from the noisy increments
};

inline Eigen::Vector4d plane(double nx, double ny, double nz, double d) {
  const Eigen::Vector3d n = Eigen::Vector3d(nx, ny, nz).normalized();
  return Eigen::Vector4d(n.x(), n.y(), n.z(), d);
}

inline PlaneWorld make_plane_world(int steps, std::uint64_t seed) {
  PlaneWorld w;
  w.planes = {plane(0, 0, 1, 0),   plane(1, 0, 0, 20), plane(1, 0, 0, -20),   plane(0, 1, 0, 18),
              plane(0, 1, 0, -22), plane(1, 1, 0, 24), plane(1, -1, 0.1, 26), plane(0.1, 0.2, 1, 12)};
  const double sigma_t = 0.03, sigma_a = 0.004, bias_yaw = 0.006, bias_x = 0.02;
  const double sigma_n = 0.01, sigma_d = 0.05;
  w.Q = Eigen::VectorXd(
            (Eigen::VectorXd(6) << sigma_t, sigma_t, sigma_t, sigma_a, sigma_a, 2 * sigma_a).finished())
            .array()
            .square()
            .matrix()
            .asDiagonal();
  w.Q(0, 0) += bias_x * bias_x;
  w.Q(5, 5) += bias_yaw * bias_yaw;
  w.R = Eigen::Vector4d(sigma_n * sigma_n, sigma_n * sigma_n, sigma_n * sigma_n, sigma_d * sigma_d)
            .asDiagonal();
  Rng rng(seed);
  const PlaneSlamModel model;
  auto observe = [&](const Pose6& pose) {
    std::vector<SlamObservation> out;
    for (std::size_t i = 0; i < w.planes.size(); ++i) {
      Eigen::VectorXd z = model.observe(pose.vector(), w.planes[i]);
      z.head<3>() += test::normal_draws<3>(rng, sigma_n);
      z.head<3>().normalize();
      z[3] += sigma_d * rng.normal();
      out.push_back({z, static_cast<int>(i)});
    }
    return out;
  };
  for (int k = 0; k <= steps; ++k) {
    const double t = 2.0 * M_PI * k / steps;
    w.truth.push_back(Pose6{8.0 * std::sin(t), 8.0 * (1.0 - std::cos(t)), 0.3 * std::sin(2 * t),
                            0.03 * std::sin(3 * t), 0.02 * std::cos(2 * t), wrap_angle(t)});
  }
  for (const SlamObservation& o : observe(w.truth[0])) w.first_observations.push_back(o.z);
  w.odometry.push_back(w.truth[0]);
  for (int k = 0; k < steps; ++k) {
    Eigen::VectorXd u = odometry_increment(w.truth[k], w.truth[k + 1]);
    for (int i = 0; i < 6; ++i) u[i] += (i < 3 ? sigma_t : sigma_a) * rng.normal();
    u[0] += bias_x;
    u[5] += bias_yaw;
    w.steps.push_back({u, observe(w.truth[k + 1])});
    w.odometry.push_back(Pose6::from_vector(model.process(w.odometry.back().vector(), u)));
  }
  return w;
}

/// Initialises `filter` at the true start with a tight prior and the first observations as landmarks.
/// Returns the id → index map of those landmarks for run_slam.
template <class FilterT>
std::map<int, int> start_plane_slam(FilterT& filter, const PlaneWorld& w, double prior_sigma = 1e-3) {
  filter.initialize(w.truth[0].vector(), Eigen::MatrixXd::Identity(6, 6) * prior_sigma * prior_sigma);
  std::map<int, int> known;
  for (const Eigen::VectorXd& z : w.first_observations) {
    filter.augment(z, w.R);
    known[static_cast<int>(known.size())] = filter.num_landmarks() - 1;
  }
  return known;
}

/// Starts `filter` at the origin and adds `planes` random planes, with a motion update (0.5 m,
/// 0.01 rad) after each: the growing map of the SEIF cost and Markov-blanket tests.
template <class FilterT>
void grow_random_plane_map(FilterT& filter, int planes, std::uint64_t seed) {
  filter.initialize(Eigen::VectorXd::Zero(6), Eigen::MatrixXd::Identity(6, 6) * 1e-4);
  Rng rng(seed);
  const Eigen::Matrix4d R = Eigen::Vector4d(1e-4, 1e-4, 1e-4, 1e-2).asDiagonal();
  Eigen::VectorXd u(6);
  u << 0.5, 0.0, 0.0, 0.0, 0.0, 0.01;
  const Eigen::MatrixXd Q = Eigen::MatrixXd::Identity(6, 6) * 1e-4;
  for (int i = 0; i < planes; ++i) {
    Eigen::VectorXd z(4);
    z << test::normal_draws<3>(rng).normalized(), rng.uniform(1.0, 20.0);
    EXPECT_TRUE(filter.augment(z, R).ok());
    EXPECT_TRUE(filter.predict(u, Q).ok());
  }
}

inline double position_error(const Eigen::VectorXd& pose, const Pose6& truth) {
  return (pose.head<3>() - Eigen::Vector3d(truth.x, truth.y, truth.z)).norm();
}

}  // namespace sextant::test
