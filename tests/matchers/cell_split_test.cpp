// The splitting process's two passes (cell_split.hpp, white-box): every point's cell, with the grid
// closed on its far face and anything outside or not finite left out, and every occupied cell's sums
// as one-point-at-a-time code adds them, in the same order. On x86-64 the passes are compiled for
// plain x86-64 and for AVX2: both must give the same bits (EXPECT_EQ on doubles, not NEAR).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "ndt/cell_split.hpp"
#include "sextant/core/rng.hpp"

namespace sextant::ndt_detail {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

/// 5 × 4 × 3 cells of 0.5 m from (−1, 2, 0.5).
SplitGrid grid() {
  return SplitGrid{-1.0, 2.0, 0.5, 2.0, 5, 4, 3};
}

/// Points in and around the grid, shuffled, with the cases at its borders (1,003 points: an odd
/// count leaves a tail for the one-point code).
std::vector<Eigen::Vector3f> points() {
  Rng rng(11);
  std::vector<Eigen::Vector3f> p;
  for (int i = 0; i < 1000; ++i)
    p.emplace_back(static_cast<float>(rng.uniform(-1.3, 1.8)), static_cast<float>(rng.uniform(1.8, 4.2)),
                   static_cast<float>(rng.uniform(0.3, 2.2)));
  p.emplace_back(1.5f, 4.0f, 2.0f);   // the far corner: the last cell
  p.emplace_back(kNaN, 3.0f, 1.0f);   // not finite: outside
  p.emplace_back(0.0f, 3.0f, 1e30f);  // far above: outside
  return p;
}

/// The cell of p by its definition: floor((p − origin) / edge) along each axis, the far face in the
/// last cell.
std::uint32_t cell_by_definition(const Eigen::Vector3f& p, const SplitGrid& g) {
  const double o[3] = {g.ox, g.oy, g.oz};
  const int n[3] = {g.nx, g.ny, g.nz};
  int c[3];
  for (int a = 0; a < 3; ++a) {
    const double f = (static_cast<double>(p(a)) - o[a]) * g.inv_edge;
    if (!(f >= 0.0 && f <= n[a] + 1e-9)) return kOutside;
    c[a] = std::min(static_cast<int>(std::floor(f)), n[a] - 1);
  }
  return static_cast<std::uint32_t>((c[2] * g.ny + c[1]) * g.nx + c[0]);
}

TEST(CellSplit, EveryPointInItsCellAndTheSumsOfEachCellInPointOrder) {
  const SplitGrid g = grid();
  const std::vector<Eigen::Vector3f> p = points();
  std::vector<std::uint32_t> cells(p.size());
  assign_cells(p, g, cells.data(), InstructionSet::kBaseline);
  std::size_t outside = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(cells[i], cell_by_definition(p[i], g)) << i;
    outside += cells[i] == kOutside;
  }
  EXPECT_EQ(cells[1000], 59u) << "the far corner is in the last cell";
  EXPECT_EQ(cells[1001], kOutside);
  EXPECT_EQ(cells[1002], kOutside);
  EXPECT_GT(outside, 100u);
  EXPECT_LT(outside, 500u);

  std::vector<std::int32_t> index(60, -1);
  const std::vector<CellSums> sums =
      accumulate_cells(p, cells.data(), g, index.data(), InstructionSet::kBaseline);
  // One point at a time, relative to the origin, in the points' order.
  std::map<std::uint32_t, CellSums> expected;
  std::vector<std::uint32_t> first_seen;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (cells[i] == kOutside) continue;
    if (!expected.count(cells[i])) first_seen.push_back(cells[i]);
    CellSums& e = expected[cells[i]];
    const double d[3] = {static_cast<double>(p[i].x()) - g.ox, static_cast<double>(p[i].y()) - g.oy,
                         static_cast<double>(p[i].z()) - g.oz};
    ++e.count;
    for (int a = 0; a < 3; ++a) e.sum[a] += d[a];
    const double products[6] = {d[0] * d[0], d[0] * d[1], d[0] * d[2], d[1] * d[1], d[1] * d[2], d[2] * d[2]};
    for (int k = 0; k < 6; ++k) e.sum_sq[k] += products[k];
  }
  ASSERT_EQ(sums.size(), first_seen.size());
  for (std::size_t s = 0; s < sums.size(); ++s) {
    const std::uint32_t cell = first_seen[s];
    SCOPED_TRACE(::testing::Message() << "cell " << cell);
    EXPECT_EQ(static_cast<std::uint32_t>(sums[s].cell), cell) << "in order of first appearance";
    EXPECT_EQ(index[cell], static_cast<std::int32_t>(s));
    EXPECT_EQ(sums[s].x, static_cast<std::int32_t>(cell % 5));
    EXPECT_EQ(sums[s].y, static_cast<std::int32_t>(cell / 5 % 4));
    EXPECT_EQ(sums[s].z, static_cast<std::int32_t>(cell / 20));
    const CellSums& e = expected[cell];
    EXPECT_EQ(sums[s].count, e.count);
    for (int a = 0; a < 3; ++a) EXPECT_EQ(sums[s].sum[a], e.sum[a]) << a;
    for (int k = 0; k < 6; ++k) EXPECT_EQ(sums[s].sum_sq[k], e.sum_sq[k]) << k;
  }
  for (std::uint32_t cell = 0; cell < 60; ++cell) {
    if (!expected.count(cell)) {
      EXPECT_EQ(index[cell], -1) << cell;
    }
  }
}

TEST(CellSplit, NoPointsNoCells) {
  std::vector<std::int32_t> index(60, -1);
  for (const InstructionSet isa : {InstructionSet::kBaseline, best_instruction_set()}) {
    assign_cells(PointsView(), grid(), nullptr, isa);
    EXPECT_TRUE(accumulate_cells(PointsView(), nullptr, grid(), index.data(), isa).empty());
  }
  EXPECT_EQ(index, std::vector<std::int32_t>(60, -1));
}

void expect_same_bits(const std::vector<CellSums>& a, const std::vector<CellSums>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t s = 0; s < a.size(); ++s) {
    EXPECT_EQ(a[s].cell, b[s].cell);
    EXPECT_EQ(a[s].count, b[s].count);
    EXPECT_EQ(a[s].x, b[s].x);
    EXPECT_EQ(a[s].y, b[s].y);
    EXPECT_EQ(a[s].z, b[s].z);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(a[s].sum[k], b[s].sum[k]);
    for (int k = 0; k < 6; ++k) EXPECT_EQ(a[s].sum_sq[k], b[s].sum_sq[k]);
  }
}

TEST(CellSplit, Avx2GivesTheBaselineBits) {
  if (!instruction_set_available(InstructionSet::kAvx2)) GTEST_SKIP() << "no AVX2 here";
  const SplitGrid g = grid();
  std::vector<Eigen::Vector3f> p = points();
  // Runs of points in one cell too (a lidar's scan order): each point repeated with a small offset.
  const std::size_t shuffled = p.size();
  for (std::size_t i = 0; i < shuffled; ++i)
    for (int k = 1; k <= 3; ++k) p.push_back(p[i] + Eigen::Vector3f::Constant(0.01f * static_cast<float>(k)));
  std::vector<std::uint32_t> baseline(p.size()), avx2(p.size());
  assign_cells(p, g, baseline.data(), InstructionSet::kBaseline);
  assign_cells(p, g, avx2.data(), InstructionSet::kAvx2);
  EXPECT_EQ(baseline, avx2);
  std::vector<std::int32_t> index_baseline(60, -1), index_avx2(60, -1);
  expect_same_bits(accumulate_cells(p, baseline.data(), g, index_baseline.data(), InstructionSet::kBaseline),
                   accumulate_cells(p, avx2.data(), g, index_avx2.data(), InstructionSet::kAvx2));
  EXPECT_EQ(index_baseline, index_avx2);
}

}  // namespace
}  // namespace sextant::ndt_detail
