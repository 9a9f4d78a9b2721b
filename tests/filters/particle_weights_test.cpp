// Log weights, the effective sample size and systematic resampling (particle_weights.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sextant/filters/particle_weights.hpp"

namespace sextant {
namespace {

std::vector<double> logs(const std::vector<double>& w) {
  std::vector<double> out;
  for (double x : w) out.push_back(std::log(x));
  return out;
}

TEST(ParticleWeights, NormalisesInLogSpaceWithoutUnderflow) {
  // exp(−1e6) underflows to 0 for every entry: linear normalisation would give 0/0.
  std::vector<double> lw{-1e6, -1e6 - std::log(3.0), -2e6, -std::numeric_limits<double>::infinity()};
  ASSERT_TRUE(normalize_log_weights(lw));
  const std::vector<double> w = weights_from_log(lw);
  // lw ≈ −1e6 carries ulp(1e6) ≈ 1e-10 of rounding: the ratio of the weights is that exact.
  EXPECT_NEAR(w[0], 0.75, 1e-9);
  EXPECT_NEAR(w[1], 0.25, 1e-9);
  EXPECT_NEAR(w[0] + w[1] + w[2] + w[3], 1.0, 1e-15);
  EXPECT_EQ(w[2], 0.0);
  EXPECT_EQ(w[3], 0.0);
  for (double x : w) EXPECT_TRUE(std::isfinite(x));
  std::vector<double> none{-std::numeric_limits<double>::infinity()};
  EXPECT_FALSE(normalize_log_weights(none));
}

TEST(ParticleWeights, EffectiveSampleSizeIsOneOverSumOfSquares) {
  EXPECT_NEAR(effective_sample_size(logs({0.25, 0.25, 0.25, 0.25})), 4.0, 1e-12);
  EXPECT_NEAR(effective_sample_size(logs({0.5, 0.25, 0.25})), 1.0 / (0.25 + 0.0625 + 0.0625), 1e-12);
  EXPECT_NEAR(effective_sample_size(logs({1.0, 1e-300, 1e-300})), 1.0, 1e-12);
}

// Over many draws (fixed seed), systematic resampling draws particle i N w_i times on average.
// Each count is ⌊N w_i⌋ or ⌈N w_i⌉ (next test), so its variance is at most 1/4 and the mean of
// 4000 draws is within 0.04 (5σ) of N w_i.
TEST(ParticleWeights, SystematicResamplingKeepsCountsProportionalToWeights) {
  const std::size_t n = 37;
  std::vector<double> w(n);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += (w[i] = 1.0 + static_cast<double>((i * 7) % 11));
  for (double& x : w) x /= sum;
  Rng rng(5);
  std::vector<double> mean_count(n, 0.0);
  const int draws = 4000;
  for (int d = 0; d < draws; ++d) {
    const std::vector<std::size_t> idx = systematic_resample(logs(w), rng);
    ASSERT_EQ(idx.size(), n);
    for (std::size_t i : idx) mean_count[i] += 1.0 / draws;
  }
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(mean_count[i], static_cast<double>(n) * w[i], 0.04) << i;
}

TEST(ParticleWeights, SystematicResamplingCountsAreFloorOrCeilOfNw) {
  Rng rng(9);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = 1 + rng.index(60);
    std::vector<double> w(n);
    double sum = 0.0;
    for (double& x : w) sum += (x = std::pow(rng.uniform(), 3.0));
    for (double& x : w) x /= sum;
    const std::vector<std::size_t> idx = systematic_resample(logs(w), rng);
    ASSERT_EQ(idx.size(), n);
    std::vector<int> count(n, 0);
    for (std::size_t i : idx) ++count[i];
    for (std::size_t i = 0; i < n; ++i) {
      const double nw = static_cast<double>(n) * w[i];
      EXPECT_GE(count[i], std::floor(nw - 1e-9)) << trial << " " << i;
      EXPECT_LE(count[i], std::ceil(nw + 1e-9)) << trial << " " << i;
    }
  }
}

}  // namespace
}  // namespace sextant
