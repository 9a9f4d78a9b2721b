// inflated_inverse against V max(Λ, floor)⁻¹ Vᵀ from known eigenvectors and eigenvalues: in each case
// of raised eigenvalues and at the case boundaries, where the spectral gaps vanish.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "sextant/core/rng.hpp"
#include "sextant/matchers/cell_covariance.hpp"

namespace sextant {
namespace {

struct Spectrum {
  Eigen::Vector3d values;  // ascending
  double ratio;            // floor = λ₂ / ratio
};

Eigen::Matrix3d random_rotation(Rng& rng) {
  Eigen::Quaterniond q(rng.normal(), rng.normal(), rng.normal(), rng.normal());
  return q.normalized().toRotationMatrix();
}

/// Spectra of every kind a cell has: a ball, planes, lines, rank-deficient, repeated eigenvalues, and
/// eigenvalues a hair either side of the floor λ₂ / ratio.
std::vector<Spectrum> spectra() {
  const double f = 0.01;  // the floor for λ₂ = 1 and ratio 100
  return {
      {{0.2, 0.5, 1.0}, 100.0},            // nothing raised
      {{1e-5, 0.3, 1.0}, 100.0},           // a plane: λ₀ raised
      {{1e-6, 2e-4, 1.0}, 100.0},          // a line: λ₀ and λ₁ raised
      {{0.0, 0.0, 1.0}, 100.0},            // rank one
      {{1e-4, 1.0, 1.0}, 100.0},           // a round plane: λ₁ = λ₂
      {{1e-4, 1e-4, 1.0}, 100.0},          // a thin line: λ₀ = λ₁ below the floor
      {{1.0, 1.0, 1.0}, 100.0},            // a ball
      {{f * (1 - 1e-12), f, 1.0}, 100.0},  // λ₀ a hair below the floor, λ₁ on it
      {{f * (1 - 1e-9), f * (1 + 1e-12), 1.0}, 100.0},
      {{f * 0.5, f * (1 - 1e-13), 1.0}, 100.0},  // λ₁ a hair below the floor
      {{0.3, 1.0 - 1e-13, 1.0}, 1.0},            // ratio 1: everything raised to λ₂
      {{-1e-17, 0.4, 1.0}, 100.0},               // a rounding below zero
      {{2e-9, 5e-7, 3e-4}, 100.0},               // small numbers: a 2 cm cell
  };
}

TEST(CellCovariance, InflatedInverseIsTheInverseOfTheRaisedSpectrum) {
  Rng rng(7);
  for (const Spectrum& s : spectra()) {
    for (int trial = 0; trial < 50; ++trial) {
      const Eigen::Matrix3d V = random_rotation(rng);
      const Eigen::Matrix3d C = V * s.values.asDiagonal() * V.transpose();
      const double floor = s.values(2) / s.ratio;
      const Eigen::Vector3d raised = s.values.cwiseMax(floor);
      const Eigen::Matrix3d expected = V * raised.cwiseInverse().asDiagonal() * V.transpose();
      // As cell_gaussian calls it: with the eigenvalues computed from C, not the exact ones.
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
      eig.computeDirect(C, Eigen::EigenvaluesOnly);
      const Eigen::Vector3d l = eig.eigenvalues();
      const Eigen::Matrix3d got = inflated_inverse(C, l, l(2) / s.ratio);
      ASSERT_TRUE(got.allFinite()) << s.values.transpose();
      // The closed-form eigenvalues of a (nearly) repeated root carry errors of about √ε, which
      // an inverse built from the computed eigenvectors shares: the bar is that inverse's error.
      eig.computeDirect(C);
      const Eigen::Matrix3d& W = eig.eigenvectors();
      const Eigen::Matrix3d from_vectors =
          W * eig.eigenvalues().cwiseMax(l(2) / s.ratio).cwiseInverse().asDiagonal() * W.transpose();
      const double error = (got - expected).norm() / expected.norm();
      const double vectors_error = (from_vectors - expected).norm() / expected.norm();
      EXPECT_LE(error, std::max(2.0 * vectors_error, 1e-12))
          << "spectrum " << s.values.transpose() << ", trial " << trial << ", with eigenvectors "
          << vectors_error;
      EXPECT_LT(error, 1e-6)  // about √ε · λ₂ / floor at most
          << "spectrum " << s.values.transpose() << ", trial " << trial;
    }
  }
}

}  // namespace
}  // namespace sextant
