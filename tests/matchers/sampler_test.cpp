#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "sextant/core/error.hpp"
#include "sextant/matchers/samplers.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant {
namespace {

PointCloud line_cloud(std::size_t n, float spacing) {
  PointCloud cloud;
  for (std::size_t i = 0; i < n; ++i) cloud.push_back({spacing * static_cast<float>(i) + 0.05f, 0.5f, 0.5f});
  return cloud;
}

TEST(Sampler, AllKeepsEverything) {
  Rng rng(1);
  const SampleResult r = sample_points(*make_sampler("all"), line_cloud(17, 0.1f), rng);
  EXPECT_EQ(r.indices.size(), 17u);
  EXPECT_DOUBLE_EQ(r.kept_fraction, 1.0);
}

TEST(Sampler, RegularTakesEveryKth) {
  Rng rng(1);
  const SampleResult r =
      sample_points(*make_sampler("regular", YAML::Load("{step: 4}")), line_cloud(10, 0.1f), rng);
  EXPECT_EQ(r.indices, (std::vector<std::size_t>{0, 4, 8}));
  EXPECT_DOUBLE_EQ(r.kept_fraction, 0.3);
}

TEST(Sampler, RandomIsSeededSortedAndUnique) {
  const auto sampler = make_sampler("random", YAML::Load("{fraction: 0.25}"));
  Rng a(7), b(7);
  const auto ra = sampler->select(line_cloud(400, 0.1f), a);
  const auto rb = sampler->select(line_cloud(400, 0.1f), b);
  EXPECT_EQ(ra, rb);
  ASSERT_EQ(ra.size(), 100u);
  for (std::size_t i = 1; i < ra.size(); ++i) EXPECT_LT(ra[i - 1], ra[i]);
}

TEST(Sampler, GridKeepsAtMostFivePerCellAndDropsSparseCells) {
  // 10 cells of 1 m along x: cell c holds c+1 points (1..10 points).
  PointCloud cloud;
  for (int c = 0; c < 10; ++c)
    for (int j = 0; j <= c; ++j) cloud.push_back({c + 0.05f + 0.09f * j, 0.5f, 0.5f});
  Rng rng(3);
  const SampleResult r = sample_points(*make_sampler("gbs"), cloud, rng);
  // cells with 1, 2 points: dropped; 3, 4, 5: all; 6..10: five each.
  EXPECT_EQ(r.indices.size(), 3u + 4u + 5u + 5u * 5u);
  std::vector<int> per_cell(10, 0);
  for (std::size_t i : r.indices) ++per_cell[static_cast<int>(cloud[i].x())];
  EXPECT_EQ(per_cell, (std::vector<int>{0, 0, 3, 4, 5, 5, 5, 5, 5, 5}));
  EXPECT_NEAR(r.kept_fraction, 37.0 / 55.0, 1e-12);
}

/// GBS by its definition: (cell key, index) pairs sorted, so cells come in key order (x, y, z
/// fields of 21 bits each, x most significant, wrapping) and points in index order; per cell a
/// partial Fisher–Yates draw of min(size, 5) points, cells of fewer than 3 dropped.
std::vector<std::size_t> gbs_by_sorting_pairs(const PointCloud& input, Rng& rng) {
  const auto field = [](float v) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v * 1.0)) & 0x1FFFFF);
  };
  std::vector<std::pair<std::uint64_t, std::size_t>> keyed;
  for (std::size_t i = 0; i < input.size(); ++i)
    if (input[i].allFinite())
      keyed.emplace_back((field(input[i].x()) << 42) | (field(input[i].y()) << 21) | field(input[i].z()), i);
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::size_t> selected, cell;
  for (std::size_t begin = 0; begin < keyed.size();) {
    cell.clear();
    std::size_t end = begin;
    while (end < keyed.size() && keyed[end].first == keyed[begin].first) cell.push_back(keyed[end++].second);
    begin = end;
    if (cell.size() < 3) continue;
    const std::size_t keep = std::min<std::size_t>(cell.size(), 5);
    for (std::size_t i = 0; i < keep; ++i) std::swap(cell[i], cell[i + rng.index(cell.size() - i)]);
    selected.insert(selected.end(), cell.begin(), cell.begin() + static_cast<std::ptrdiff_t>(keep));
  }
  std::sort(selected.begin(), selected.end());
  return selected;
}

TEST(Sampler, GridDrawsTheSamePointsAsSortingTheCellKeyIndexPairs) {
  // Points around the origin (negative cell indices wrap in the key) with NaNs and infinities.
  Rng layout(11);
  PointCloud cloud;
  for (int i = 0; i < 30000; ++i)
    cloud.push_back({static_cast<float>(layout.uniform(-40, 40)), static_cast<float>(layout.uniform(-40, 40)),
                     static_cast<float>(layout.normal(0.0, 3.0))});
  for (std::size_t i = 0; i < cloud.size(); i += 997)
    cloud.mutable_points()[i].y() = std::numeric_limits<float>::quiet_NaN();
  cloud.mutable_points()[5].z() = std::numeric_limits<float>::infinity();
  const auto gbs = make_sampler("gbs");
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    Rng a(seed), b(seed);
    EXPECT_EQ(gbs->select(cloud, a), gbs_by_sorting_pairs(cloud, b)) << "seed " << seed;
  }
}

TEST(Sampler, BadSettingsNameTheKey) {
  EXPECT_THROW(make_sampler("gbs", YAML::Load("{cell_size: -1}")), InputError);
  EXPECT_THROW(make_sampler("gbs", YAML::Load("{cel_size: 1}")), InputError);
  EXPECT_THROW(make_sampler("random", YAML::Load("{fraction: 2}")), InputError);
  EXPECT_THROW(make_sampler("nope"), InputError);  // names the file and the known samplers
}

}  // namespace
}  // namespace sextant
