// The Mahalanobis kernel's instruction sets (mahalanobis_kernel.cpp, white-box): on x86-64 it is
// compiled for plain x86-64 and for AVX2, chosen by the CPU at run time. A result must not depend on
// the CPU it ran on, so both must give the same bits: EXPECT_EQ on doubles, not NEAR.
#include <gtest/gtest.h>

#include <limits>

#include "ndt/mahalanobis_kernel.hpp"
#include "ndt/ndt_score.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/matchers/ndt_grid.hpp"
#include "test_clouds.hpp"

namespace sextant::score_detail {
namespace {

void expect_same_bits(const Sums& a, const Sums& b) {
  EXPECT_EQ(a.score, b.score);
  EXPECT_EQ(a.matched, b.matched);
  EXPECT_EQ(a.rejected, b.rejected);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(a.g_t(i), b.g_t(i)) << "g_t " << i;
    for (int j = 0; j < 3; ++j) {
      EXPECT_EQ(a.N(i, j), b.N(i, j)) << "N " << i << j;
      EXPECT_EQ(a.P(i, j), b.P(i, j)) << "P " << i << j;
      EXPECT_EQ(a.Q(i, j), b.Q(i, j)) << "Q " << i << j;
      EXPECT_EQ(a.S(i, j), b.S(i, j)) << "S " << i << j;
    }
  }
}

TEST(KernelInstructionSet, Avx2GivesTheBaselineBits) {
  if (!instruction_set_available(InstructionSet::kAvx2)) GTEST_SKIP() << "no AVX2 here";
  Rng rng(7);
  const PointCloud reference = test::yard(rng);
  LayerPyramidSettings settings;
  settings.layers = 4;
  const NdtGrid grid = build_layer_pyramid(reference, settings).back();
  ASSERT_GT(grid.gaussian_count(), 100u);
  // The input: the reference moved off the identity, 1,001 points (an odd count: padding lanes).
  const PointCloud input = reference.subset([&] {
    std::vector<std::size_t> indices;
    for (std::size_t i = 0; i < 1001; ++i) indices.push_back(i * reference.size() / 1001);
    return indices;
  }());
  const Eigen::Matrix3d R =
      (Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  const Eigen::Vector3d t(0.3, -0.2, 0.05);
  const Eigen::Vector3f* begin = input.points().data();
  for (const double max_q : {std::numeric_limits<double>::infinity(), 4.0}) {  // 4: some points beyond
    for (const Derivatives d : {Derivatives::kScore, Derivatives::kGradient, Derivatives::kHessian}) {
      Sums baseline, avx2;
      mahalanobis_block(grid, begin, begin + input.size(), R, t, max_q, d, baseline,
                        InstructionSet::kBaseline);
      mahalanobis_block(grid, begin, begin + input.size(), R, t, max_q, d, avx2, InstructionSet::kAvx2);
      SCOPED_TRACE(::testing::Message() << "max_q " << max_q << ", derivatives " << static_cast<int>(d));
      ASSERT_GT(baseline.matched, max_q < 10.0 ? 100u : 500u);
      if (max_q < 10.0) {
        EXPECT_GT(baseline.rejected, 100u);
      }
      expect_same_bits(baseline, avx2);
    }
  }
}

TEST(KernelInstructionSet, TheBestIsAvailableAndTheBaselineAlwaysIs) {
  EXPECT_TRUE(instruction_set_available(InstructionSet::kBaseline));
  EXPECT_TRUE(instruction_set_available(best_instruction_set()));
}

}  // namespace
}  // namespace sextant::score_detail
