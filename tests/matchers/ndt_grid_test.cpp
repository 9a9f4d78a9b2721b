#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "sextant/matchers/ndt_grid.hpp"
#include "test_clouds.hpp"

namespace sextant {
namespace {

TEST(LayerGeometry, ThesisWorkedExample) {
  // §3.2: a 100 × 100 × 20 m cloud, layer 2 with q = 8 → k = 3125^(1/3) = 14.62 m, 7 × 7 × 2 cells.
  Bounds b;
  b.min = {-50, -50, 0};
  b.max = {50, 50, 20};
  const LayerGeometry g = layer_geometry(b, 8, 2);
  EXPECT_NEAR(g.cell_edge, 14.62, 0.005);
  EXPECT_EQ(g.dims, Eigen::Vector3i(7, 7, 2));
  EXPECT_EQ(g.dims.prod(), 98);
}

TEST(LayerGeometry, FlatCloudUsesArea) {
  Bounds b;
  b.min = {0, 0, 0};
  b.max = {40, 40, 0};
  const LayerGeometry g = layer_geometry(b, 4, 1);
  EXPECT_NEAR(g.cell_edge, 20.0, 1e-9);
  EXPECT_EQ(g.dims, Eigen::Vector3i(2, 2, 1));
}

TEST(NdtGrid, MeanCovarianceAndLookup) {
  Rng rng(5);
  PointCloud cloud;
  std::vector<Eigen::Vector3d> in_cell;
  for (int i = 0; i < 200; ++i) {
    const auto z = static_cast<float>(rng.uniform()), y = static_cast<float>(rng.uniform()),
               x = static_cast<float>(rng.normal());
    const Eigen::Vector3f p(1.5f + 0.3f * x * 0.5f, 0.5f + 0.1f * y, 0.5f + 0.2f * z);
    cloud.push_back(p);
  }
  for (int i = 0; i < 3; ++i) cloud.push_back({0.5f, 2.5f, 0.5f});  // too few for a Gaussian
  const NdtGrid grid = NdtGrid::build(cloud, Eigen::Vector3d::Zero(), 1.0, {3, 3, 1});
  ASSERT_EQ(grid.gaussian_count(), 1u);
  const int g = grid.lookup(1.5f, 0.5f, 0.5f);
  ASSERT_EQ(g, 0);
  EXPECT_EQ(grid.lookup(0.5f, 2.5f, 0.5f), -1);
  EXPECT_EQ(grid.lookup(-0.1f, 0.5f, 0.5f), -1);
  EXPECT_EQ(grid.lookup(std::nanf(""), 0.5f, 0.5f), -1);
  EXPECT_EQ(grid.cell_of(g), Eigen::Vector3i(1, 0, 0));
  // Reference statistics, eqs. (3.2)–(3.3), over the points inside cell (1, 0, 0).
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  int n = 0;
  for (const auto& p : cloud.points())
    if (p.x() >= 1 && p.x() < 2 && p.y() < 1) mean += p.cast<double>(), ++n;
  mean /= n;
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (const auto& p : cloud.points())
    if (p.x() >= 1 && p.x() < 2 && p.y() < 1)
      C += (p.cast<double>() - mean) * (p.cast<double>() - mean).transpose();
  C /= (n - 1);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(grid.gaussian(g).mean[i], mean(i), 1e-5);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C);
  const Eigen::Vector3d l = eig.eigenvalues();
  if (l(2) / l(0) <= 100.0) {
    EXPECT_LT((grid.covariance(g) - C).norm(), 1e-5 * C.norm());  // C'⁻¹ is stored in float
  }
}

// split() sums a run of consecutive points in one cell in registers (scan order): every cell must
// come out bit for bit as when its points arrive interleaved with another cell's, and as when a
// cell's points come in several runs, with the cell changing between them.
TEST(NdtGrid, RunsOfPointsInOneCellSumAsPointsOneAtATime) {
  Rng rng(11);
  std::vector<Eigen::Vector3f> a, b;  // cells (0, 0, 0) and (1, 0, 0)
  for (int i = 0; i < 40; ++i) {
    a.emplace_back(0.9f * static_cast<float>(rng.uniform()), 0.9f * static_cast<float>(rng.uniform()),
                   0.9f * static_cast<float>(rng.uniform()));
    b.emplace_back(1.05f + 0.9f * static_cast<float>(rng.uniform()), 0.9f * static_cast<float>(rng.uniform()),
                   0.3f * static_cast<float>(rng.uniform()));
  }
  PointCloud runs, interleaved, chunks;  // a…a b…b; a b a b …; 10 a, 10 b, 10 a, …
  for (const auto& p : a) runs.push_back(p);
  for (const auto& p : b) runs.push_back(p);
  for (std::size_t i = 0; i < a.size(); ++i) interleaved.push_back(a[i]), interleaved.push_back(b[i]);
  for (std::size_t i = 0; i < a.size(); i += 10) {
    for (std::size_t j = i; j < i + 10; ++j) chunks.push_back(a[j]);
    for (std::size_t j = i; j < i + 10; ++j) chunks.push_back(b[j]);
  }
  const auto build = [](const PointCloud& cloud) {
    return NdtGrid::build(cloud, Eigen::Vector3d::Zero(), 1.0, {2, 1, 1});
  };
  const NdtGrid expected = build(runs);
  ASSERT_EQ(expected.gaussian_count(), 2u);
  EXPECT_NEAR(expected.gaussian(expected.lookup(0.5f, 0.5f, 0.5f)).mean[1], 0.45, 0.1);
  for (const PointCloud* cloud : {&interleaved, &chunks}) {
    const NdtGrid grid = build(*cloud);
    ASSERT_EQ(grid.gaussian_count(), 2u);
    for (const float x : {0.5f, 1.5f}) {
      const CellGaussian &want = expected.gaussian(expected.lookup(x, 0.5f, 0.5f)),
                         &got = grid.gaussian(grid.lookup(x, 0.5f, 0.5f));
      for (int i = 0; i < 3; ++i) EXPECT_EQ(got.mean[i], want.mean[i]) << "cell at x = " << x;
      for (int i = 0; i < 6; ++i) EXPECT_EQ(got.inv_cov[i], want.inv_cov[i]) << "cell at x = " << x;
    }
  }
}

TEST(NdtGrid, CoplanarCellIsInflatedToRatio100) {
  PointCloud cloud;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) cloud.push_back({0.05f + 0.09f * i, 0.05f + 0.09f * j, 0.5f});
  const NdtGrid grid = NdtGrid::build(cloud, Eigen::Vector3d::Zero(), 1.0, {1, 1, 1});
  ASSERT_EQ(grid.gaussian_count(), 1u);
  const Eigen::Vector3d l = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(grid.covariance(0)).eigenvalues();
  EXPECT_NEAR(l(0) / (l(2) / 100.0), 1.0, 1e-5);  // C'⁻¹ is stored in float
  EXPECT_TRUE(std::isfinite(grid.gaussian(0).inv_cov[5]));
  const Eigen::Matrix3d Lt = grid.sqrt_information(0);
  EXPECT_TRUE(Lt.isUpperTriangular());
  const Eigen::Matrix3d inv = grid.covariance(0).inverse();
  EXPECT_LT((Lt.transpose() * Lt - inv).norm() / inv.norm(), 1e-5);
}

TEST(NdtGrid, PyramidLayerSizesGrowByQ) {
  Rng rng(2);
  const PointCloud cloud = test::yard(rng);
  const auto layers = build_layer_pyramid(cloud, LayerPyramidSettings{});
  ASSERT_EQ(layers.size(), 4u);
  for (std::size_t i = 1; i < layers.size(); ++i) {
    EXPECT_NEAR(layers[i - 1].cell_edge() / layers[i].cell_edge(), 2.0, 1e-9);  // q = 8 → edge halves
    EXPECT_GT(layers[i].gaussian_count(), layers[i - 1].gaussian_count());
  }
}

/// The same cells and Gaussians, up to the rounding of the summation order; returns how many.
std::size_t expect_same_gaussians(const NdtGrid& nested, const NdtGrid& direct, int layer) {
  EXPECT_NEAR(nested.cell_edge(), direct.cell_edge(), 1e-12 * direct.cell_edge()) << layer;
  EXPECT_EQ(nested.dims(), direct.dims()) << layer;
  EXPECT_EQ(nested.gaussian_count(), direct.gaussian_count()) << layer;
  if (nested.gaussian_count() != direct.gaussian_count()) return 0;
  for (int k = 0; k < static_cast<int>(direct.gaussian_count()); ++k) {
    EXPECT_EQ(nested.cell_of(k), direct.cell_of(k)) << layer << " " << k;
    const CellGaussian &n = nested.gaussian(k), &d = direct.gaussian(k);
    for (int m = 0; m < 3; ++m) EXPECT_NEAR(n.mean[m], d.mean[m], 1e-5f * (1.0f + std::abs(d.mean[m])));
    float scale = 0.0f;
    for (const float v : d.inv_cov) scale = std::max(scale, std::abs(v));
    for (int m = 0; m < 6; ++m) EXPECT_NEAR(n.inv_cov[m], d.inv_cov[m], 1e-4f * scale) << layer << " " << k;
  }
  return direct.gaussian_count();
}

// With q = 8 the pyramid builds its finest layer from the points and every coarser layer from
// its children's sums: the same cells and Gaussians as building each layer from the points, up
// to the rounding of the summation order.
TEST(NdtGrid, NestedPyramidMatchesLayerByLayerBuild) {
  Rng rng(3);
  const PointCloud cloud = test::yard(rng, 2);
  LayerPyramidSettings settings;
  settings.layers = 5;
  const auto layers = build_layer_pyramid(cloud, settings);
  ASSERT_EQ(layers.size(), 5u);
  const Bounds b = cloud.bounds();
  std::size_t compared = 0;
  for (int i = 1; i <= 5; ++i) {
    const LayerGeometry g = layer_geometry(b, 8, i);
    EXPECT_EQ(layers[static_cast<std::size_t>(i - 1)].dims(), g.dims) << i;
    compared += expect_same_gaussians(layers[static_cast<std::size_t>(i - 1)],
                                      NdtGrid::build(cloud, b.min.cast<double>(), g.cell_edge, g.dims), i);
  }
  EXPECT_GT(compared, 100u);
}

// With `finer`, the one split is into layer n + 1 (ML-NDT's aligned precision grid): that grid is
// exactly the one built from the points on its own, and the pyramid above it is unchanged.
TEST(NdtGrid, PyramidWithItsFinerLayerMatchesDirectBuilds) {
  Rng rng(3);
  const PointCloud cloud = test::yard(rng, 2);
  LayerPyramidSettings settings;
  settings.layers = 4;
  const Bounds b = cloud.bounds();
  ASSERT_TRUE(pyramid_nests(b, settings));
  NdtGrid finer;
  const auto layers = build_layer_pyramid(cloud, settings, b, &finer);
  ASSERT_EQ(layers.size(), 4u);
  const LayerGeometry last = layer_geometry(b, 8, 4);
  const NdtGrid direct = NdtGrid::build(cloud, b.min.cast<double>(), 0.5 * last.cell_edge, 2 * last.dims);
  ASSERT_GT(direct.gaussian_count(), 100u);
  ASSERT_EQ(finer.gaussian_count(), direct.gaussian_count());
  EXPECT_EQ(finer.modelled_points(), direct.modelled_points());
  for (int k = 0; k < static_cast<int>(direct.gaussian_count()); ++k) {  // the same sums: equal
    ASSERT_EQ(finer.cell_of(k), direct.cell_of(k)) << k;
    for (int m = 0; m < 3; ++m) EXPECT_EQ(finer.gaussian(k).mean[m], direct.gaussian(k).mean[m]) << k;
    for (int m = 0; m < 6; ++m) EXPECT_EQ(finer.gaussian(k).inv_cov[m], direct.gaussian(k).inv_cov[m]) << k;
  }
  const auto alone = build_layer_pyramid(cloud, settings, b);
  for (int i = 0; i < 4; ++i)
    expect_same_gaussians(layers[static_cast<std::size_t>(i)], alone[static_cast<std::size_t>(i)], i + 1);
  // Layers that do not nest (q = 4: edges shrink by 4^(1/3)) leave `finer` to the caller.
  settings.division = 4;
  EXPECT_FALSE(pyramid_nests(b, settings));
  build_layer_pyramid(cloud, settings, b, &finer);
  EXPECT_EQ(finer.cell_count(), 0u);
}

TEST(NdtGrid, EmptyAndDegenerateInputGiveEmptyGrids) {
  EXPECT_TRUE(NdtGrid::build_over_bounds(PointCloud(), 1.0).empty());
  PointCloud collinear;
  for (int i = 0; i < 50; ++i) collinear.push_back({0.1f * i, 0, 0});
  const NdtGrid grid = NdtGrid::build_over_bounds(collinear, 1.0);
  for (std::size_t g = 0; g < grid.gaussian_count(); ++g)
    EXPECT_TRUE(grid.covariance(static_cast<int>(g)).allFinite());
  EXPECT_TRUE(NdtGrid::build_over_bounds(collinear, -1.0).empty());
  EXPECT_TRUE(NdtGrid::build(collinear, Eigen::Vector3d::Zero(), 1e-4, {100000, 100000, 100000}).too_large());
}

// Cell indices are 32-bit: a grid of 2³¹ cells or more is refused even when the caller allows more.
TEST(NdtGrid, NeverIndexesMoreCellsThan32BitsHold) {
  PointCloud cloud;
  for (int i = 0; i < 50; ++i) cloud.push_back({0.1f * i, 0.05f * (i % 7), 0.02f * (i % 5)});
  const std::size_t unlimited = std::numeric_limits<std::size_t>::max();
  EXPECT_TRUE(
      NdtGrid::build(cloud, Eigen::Vector3d::Zero(), 1e-3, {2048, 1024, 1024}, {}, unlimited).too_large());
  const NdtGrid below = NdtGrid::build(cloud, Eigen::Vector3d::Zero(), 0.5, {20, 2, 2}, {}, unlimited);
  ASSERT_FALSE(below.too_large());
  ASSERT_GT(below.gaussian_count(), 3u);
  for (int g = 0; g < static_cast<int>(below.gaussian_count()); ++g) {  // a cell's mean lies in it
    const float* m = below.gaussian(g).mean;
    const Eigen::Vector3i cell(static_cast<int>(m[0] / 0.5f), static_cast<int>(m[1] / 0.5f),
                               static_cast<int>(m[2] / 0.5f));
    EXPECT_EQ(below.cell_of(g), cell) << "Gaussian " << g;
  }
}

}  // namespace
}  // namespace sextant
