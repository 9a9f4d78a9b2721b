// cell_information against V max(Λ, floor)⁻¹ Vᵀ from known eigenvectors and eigenvalues: in each case
// of raised eigenvalues and at the case boundaries, where the spectral gaps vanish; its eigenvalues
// against the known ones, and the cells it refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "ndt/cell_covariance.hpp"
#include "ndt/cell_covariance_lanes.hpp"
#include "sextant/core/rng.hpp"

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
      {{0.2, 0.5, 1.0}, 100.0},             // nothing raised
      {{1e-5, 0.3, 1.0}, 100.0},            // a plane: λ₀ raised
      {{1e-6, 2e-4, 1.0}, 100.0},           // a line: λ₀ and λ₁ raised
      {{0.0, 0.0, 1.0}, 100.0},             // rank one
      {{1e-4, 1.0, 1.0}, 100.0},            // a round plane: λ₁ = λ₂
      {{1e-4, 1e-4, 1.0}, 100.0},           // a thin line: λ₀ = λ₁ below the floor
      {{1.0, 1.0, 1.0}, 100.0},             // a ball
      {{f * (1 - 1e-12), f, 1.0}, 100.0},   // λ₀ a hair below the floor, λ₁ on it
      {{f * (1 + 1e-9), 0.5, 1.0}, 100.0},  // λ₀ a hair above it: nothing raised, not provably
      {{f * (1 - 1e-9), f * (1 + 1e-12), 1.0}, 100.0},
      {{f * 0.5, f * (1 - 1e-13), 1.0}, 100.0},  // λ₁ a hair below the floor
      {{0.3, 1.0 - 1e-13, 1.0}, 1.0},            // ratio 1: everything raised to λ₂
      {{-1e-17, 0.4, 1.0}, 100.0},               // a rounding below zero
      {{2e-9, 5e-7, 3e-4}, 100.0},               // small numbers: a 2 cm cell
  };
}

/// A matrix with the spectrum's eigenvalues in random directions, and the directions.
Eigen::Matrix3d with_spectrum(const Eigen::Vector3d& values, Rng& rng,
                              Eigen::Matrix3d* directions = nullptr) {
  const Eigen::Matrix3d V = random_rotation(rng);
  if (directions) *directions = V;
  return V * values.asDiagonal() * V.transpose();
}

// The rounding of two closed forms differs from trial to trial: each spectrum's worst error over the
// trials is compared.
TEST(CellCovariance, EigenvaluesAsAccurateAsEigensClosedForm) {
  Rng rng(3);
  for (const Spectrum& s : spectra()) {
    double worst = 0.0, eigens_worst = 0.0;
    for (int trial = 0; trial < 50; ++trial) {
      const Eigen::Matrix3d C = with_spectrum(s.values, rng);
      const Eigen::Vector3d l = symmetric_eigenvalues(C);
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
      eig.computeDirect(C, Eigen::EigenvaluesOnly);
      worst = std::max(worst, (l - s.values).cwiseAbs().maxCoeff());
      eigens_worst = std::max(eigens_worst, (eig.eigenvalues() - s.values).cwiseAbs().maxCoeff());
      EXPECT_LE(l(0), l(1));
      EXPECT_LE(l(1), l(2));
    }
    // A repeated eigenvalue is found to about √ε · λ₂ by any closed form: Eigen's error is the bar.
    EXPECT_LE(worst, std::max(2.0 * eigens_worst, 1e-14 * s.values(2)))
        << "spectrum " << s.values.transpose() << ", Eigen's worst error " << eigens_worst;
  }
}

// The roots are 2√p cos(θ + 2πk/3) for θ ∈ [0, π/3] (cell_covariance_lanes.inc), θ's cosine and sine
// from the cube root of e^(3iθ) by a fixed number of Halley steps. Away from the ends, where no
// eigenvalue repeats, every eigenvalue is found to rounding (a few ε · λ₂): one step fewer would leave
// errors of 10⁻¹⁰. At the ends (θ = 0: λ₀ = λ₁; θ = π/3: λ₁ = λ₂) the roots are found to about √ε,
// as by any closed form (Eigen's errors there are 1.6·10⁻⁹ and 1.8·10⁻⁹).
TEST(CellCovariance, EigenvaluesOverTheWholeAngleRange) {
  Rng rng(5);
  const double pi = std::acos(-1.0), lambda2 = 0.7;
  for (int step = 0; step <= 3000; ++step) {
    const double theta = pi / 3.0 * step / 3000.0;
    Eigen::Vector3d values;
    for (int k = 0; k < 3; ++k) values(k) = 0.5 + 0.2 * std::cos(theta + 2.0 * pi * k / 3.0);
    std::sort(values.data(), values.data() + 3);
    const Eigen::Vector3d l = symmetric_eigenvalues(with_spectrum(values, rng));
    const bool repeated = std::min(theta, pi / 3.0 - theta) < 0.01;
    EXPECT_LT((l - values).cwiseAbs().maxCoeff(), (repeated ? 1e-8 : 1e-14) * lambda2) << "θ = " << theta;
    EXPECT_LE(l(0), l(1));
    EXPECT_LE(l(1), l(2));
  }
}

// Many cells at once, of every kind side by side (kept, refused, and each route of cell_information):
// the batch takes the direct route four cells at a time and gathers the rest four at a time, so each
// cell's lane differs from the one it has alone. Each cell gets the bits it gets alone, and every
// instruction set gives the same bits.
TEST(CellCovariance, ABatchGivesEachCellItsOwnBitsOnEveryInstructionSet) {
  Rng rng(17);
  std::vector<Eigen::Matrix3d> cells;
  for (const Spectrum& s : spectra()) cells.push_back(with_spectrum(s.values, rng));
  cells.push_back(Eigen::Matrix3d::Zero());
  cells.push_back(-with_spectrum({0.5, 0.8, 1.0}, rng));
  Eigen::Matrix3d bad = with_spectrum({0.2, 0.5, 1.0}, rng);
  bad(1, 2) = bad(2, 1) = std::nan("");
  cells.push_back(bad);
  // Five times over: more cells than one block of the batch (64), in a count that is no multiple of 4.
  const std::size_t kinds = cells.size();
  for (int copy = 1; copy < 5; ++copy)
    for (std::size_t i = 0; i < kinds; ++i) cells.push_back(cells[i]);
  ASSERT_GT(cells.size(), 64u);
  ASSERT_NE(cells.size() % 4, 0u);
  std::vector<double> upper;
  for (const Eigen::Matrix3d& C : cells)
    for (const double e : {C(0, 0), C(0, 1), C(0, 2), C(1, 1), C(1, 2), C(2, 2)}) upper.push_back(e);
  const std::size_t n = cells.size();
  std::vector<double> baseline(6 * n), best(6 * n);
  std::unique_ptr<bool[]> kept_baseline(new bool[n]), kept_best(new bool[n]);
  ndt_detail::cells_information(upper.data(), n, 100.0, 1e-12, baseline.data(), kept_baseline.get(),
                                InstructionSet::kBaseline);
  ndt_detail::cells_information(upper.data(), n, 100.0, 1e-12, best.data(), kept_best.get(),
                                best_instruction_set());
  int kept = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Matrix3d alone;
    const bool kept_alone = cell_information(cells[i], 100.0, 1e-12, alone);
    ASSERT_EQ(kept_baseline[i], kept_alone) << "cell " << i;
    ASSERT_EQ(kept_best[i], kept_alone) << "cell " << i;
    if (!kept_alone) continue;
    ++kept;
    const double expected[6] = {alone(0, 0), alone(0, 1), alone(0, 2), alone(1, 1), alone(1, 2), alone(2, 2)};
    EXPECT_EQ(std::memcmp(expected, baseline.data() + 6 * i, sizeof expected), 0) << "cell " << i;
    EXPECT_EQ(std::memcmp(expected, best.data() + 6 * i, sizeof expected), 0) << "cell " << i;
  }
  EXPECT_EQ(kept, 5 * (static_cast<int>(kinds) - 3));  // all but the last three kinds
}

TEST(CellCovariance, InformationIsTheInverseOfTheRaisedSpectrum) {
  Rng rng(7);
  for (const Spectrum& s : spectra()) {
    double worst = 0.0, vectors_worst = 0.0;
    for (int trial = 0; trial < 50; ++trial) {
      Eigen::Matrix3d V;
      const Eigen::Matrix3d C = with_spectrum(s.values, rng, &V);
      const double floor = s.values(2) / s.ratio;
      const Eigen::Vector3d raised = s.values.cwiseMax(floor);
      const Eigen::Matrix3d expected = V * raised.cwiseInverse().asDiagonal() * V.transpose();
      Eigen::Matrix3d got;
      ASSERT_TRUE(cell_information(C, s.ratio, 0.0, got)) << s.values.transpose();
      ASSERT_TRUE(got.allFinite()) << s.values.transpose();
      EXPECT_EQ(got, got.transpose());
      // The closed-form eigenvalues of a (nearly) repeated root carry errors of about √ε, which
      // an inverse built from Eigen's eigenvalues and eigenvectors shares: the bar is its error.
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
      eig.computeDirect(C);
      const Eigen::Matrix3d& W = eig.eigenvectors();
      const double computed_floor = eig.eigenvalues()(2) / s.ratio;
      const Eigen::Matrix3d from_vectors =
          W * eig.eigenvalues().cwiseMax(computed_floor).cwiseInverse().asDiagonal() * W.transpose();
      const double error = (got - expected).norm() / expected.norm();
      worst = std::max(worst, error);
      vectors_worst = std::max(vectors_worst, (from_vectors - expected).norm() / expected.norm());
      EXPECT_LT(error, 1e-6)  // about √ε · λ₂ / floor at most
          << "spectrum " << s.values.transpose() << ", trial " << trial;
    }
    EXPECT_LE(worst, std::max(2.0 * vectors_worst, 1e-12))
        << "spectrum " << s.values.transpose() << ", with eigenvectors " << vectors_worst;
  }
}

// The same cells in any unit: the direct route's squared bounds and the eigenvalues' scaling neither
// overflow nor underflow.
TEST(CellCovariance, InformationScalesWithTheCovariance) {
  Rng rng(13);
  for (const Eigen::Vector3d& values : {Eigen::Vector3d(0.2, 0.5, 1.0), Eigen::Vector3d(1e-5, 0.3, 1.0)}) {
    Eigen::Matrix3d V;
    const Eigen::Matrix3d C = with_spectrum(values, rng, &V);
    const Eigen::Matrix3d expected = V * values.cwiseMax(0.01).cwiseInverse().asDiagonal() * V.transpose();
    for (const double unit : {1e-60, 1e-30, 1e-3, 1e30, 1e60}) {
      Eigen::Matrix3d got;
      ASSERT_TRUE(cell_information(unit * C, 100.0, 0.0, got)) << unit;
      EXPECT_LT((unit * got - expected).norm() / expected.norm(), 1e-12)
          << values.transpose() << " × " << unit;
    }
  }
}

TEST(CellCovariance, CellsWithoutSpreadOrNotFiniteAreRefused) {
  Rng rng(11);
  const Eigen::Matrix3d marker = Eigen::Matrix3d::Constant(42.0);
  Eigen::Matrix3d out = marker;
  EXPECT_FALSE(cell_information(Eigen::Matrix3d::Zero(), 100.0, 0.0, out));  // repeated points
  const Eigen::Matrix3d ball = with_spectrum({0.5, 0.8, 1.0}, rng);
  EXPECT_FALSE(cell_information(ball, 100.0, 1.0 + 1e-9, out));  // λ₂ just below the least spread
  const Eigen::Matrix3d line = with_spectrum({0.0, 0.0, 1e-4}, rng);
  EXPECT_FALSE(cell_information(line, 100.0, 2e-4, out));
  for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    Eigen::Matrix3d C = ball;
    C(0, 2) = C(2, 0) = bad;
    EXPECT_FALSE(cell_information(C, 100.0, 0.0, out)) << bad;
  }
  EXPECT_EQ(out, marker);  // untouched by every refusal
  // Negative definite (no spread at all) and a rounding below zero in every direction.
  EXPECT_FALSE(cell_information(-ball, 100.0, 0.0, out));
  EXPECT_FALSE(cell_information(with_spectrum({-3e-18, -2e-18, -1e-18}, rng), 100.0, 0.0, out));
  // At the bar, λ₂ = least spread is kept: on the direct route (a ball, trace = 3 × least spread),
  // and from the eigenvalues with nothing raised (trace below it) and with λ₀ and λ₁ raised.
  EXPECT_TRUE(cell_information(Eigen::Matrix3d::Identity(), 100.0, 1.0, out));
  EXPECT_EQ(out, Eigen::Matrix3d::Identity());
  EXPECT_TRUE(cell_information(Eigen::Vector3d(0.9, 1.0, 1.0).asDiagonal(), 100.0, 1.0, out));
  EXPECT_TRUE(cell_information(Eigen::Vector3d(0.0, 0.0, 1.0).asDiagonal(), 100.0, 1.0, out));
  EXPECT_TRUE(out.isApprox(Eigen::Vector3d(100.0, 100.0, 1.0).asDiagonal().toDenseMatrix(), 1e-14));
}

}  // namespace
}  // namespace sextant
