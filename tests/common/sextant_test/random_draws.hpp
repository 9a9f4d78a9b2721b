#pragma once
// Random vectors whose draws come in one fixed order, whatever the compiler. C++ leaves the order of
// a call's arguments unspecified: `Eigen::Vector3d(rng.normal(), rng.normal(), rng.normal())` draws
// z first under GCC and x first under clang, so the same seed gave the tests different data. These
// draw the last coordinate first, the order GCC used when the tests' thresholds were set.
#include <Eigen/Core>

#include "sextant/core/rng.hpp"

namespace sextant::test {

/// N independent N(0, sigma²) draws, the last coordinate drawn first.
template <int N>
Eigen::Matrix<double, N, 1> normal_draws(Rng& rng, double sigma = 1.0) {
  Eigen::Matrix<double, N, 1> v;
  for (int i = N - 1; i >= 0; --i) v(i) = sigma * rng.normal();
  return v;
}

/// N independent uniform draws in [lo(i), hi(i)), the last coordinate drawn first.
template <int N>
Eigen::Matrix<double, N, 1> uniform_draws(Rng& rng, const Eigen::Matrix<double, N, 1>& lo,
                                          const Eigen::Matrix<double, N, 1>& hi) {
  Eigen::Matrix<double, N, 1> v;
  for (int i = N - 1; i >= 0; --i) v(i) = rng.uniform(lo(i), hi(i));
  return v;
}

/// Three uniform draws in [0, 1), z drawn first.
inline Eigen::Vector3d unit_draws(Rng& rng) {
  return uniform_draws<3>(rng, Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
}

}  // namespace sextant::test
