// ML-NDT's precision stage (precision_stage.hpp): its grids' known edges, its settings' bounds,
// the `thesis` preset without it, and a recovered transform against the ground truth on a large
// synthetic scene whose last layer is coarse.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "pose_errors.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/units.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/samplers.hpp"
#include "sextant/matchers/yaml.hpp"
#include "test_clouds.hpp"

namespace sextant {
namespace {

/// A 200 × 200 m site: flat ground and 36 buildings on a jittered 6 × 6 lattice, densely sampled
/// (≈ 160,000 points; a 1 m ground cell holds ≈ 2 points, a 1 m wall cell ≈ 9). Its box splits into
/// 4th-layer cells of ≈ 4.5 m. The layout is fixed; `seed` draws the points.
PointCloud site(std::uint64_t seed) {
  Rng layout(7), rng(seed);
  PointCloud cloud;
  for (int i = 0; i < 80000; ++i)
    cloud.push_back({static_cast<float>(rng.uniform(-100, 100)), static_cast<float>(rng.uniform(-100, 100)),
                     0.02f * static_cast<float>(rng.normal())});
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      const auto x = static_cast<float>(-90 + 32 * i + layout.uniform(0, 8)),
                 y = static_cast<float>(-90 + 32 * j + layout.uniform(0, 8));
      const auto w = static_cast<float>(layout.uniform(4, 14)), d = static_cast<float>(layout.uniform(4, 14)),
                 h = static_cast<float>(layout.uniform(3, 9));
      test::add_box(cloud, {x, y, 0}, {x + w, y + d, h}, 2200, rng, 0.01);
    }
  }
  return cloud;
}

TEST(PrecisionStage, TwoOverlappingGridsOfLayerNPlusOnesEdge) {
  const PointCloud reference = site(1);
  MlndtSettings s;
  ASSERT_DOUBLE_EQ(s.precision.min_cell, 1.0);  // on by default
  MlndtMatcher matcher(s);
  matcher.set_reference(reference);
  const NdtGrid& last = matcher.layers().back();
  ASSERT_GT(last.cell_edge(), 4.0);  // ≈ 4.5 m: the box of 200 × 200 × 9 m in 8⁴ cubes
  ASSERT_LT(last.cell_edge(), 5.0);
  const auto edges = [&](const MlndtMatcher& m) {
    std::vector<double> out;
    for (const NdtGrid& g : m.precision_layers()) out.push_back(g.cell_edge());
    return out;
  };
  // Half the last layer's edge (above the 1 m floor), aligned and shifted by half a cell.
  const double half = 0.5 * last.cell_edge();
  ASSERT_EQ(edges(matcher), (std::vector<double>{half, half}));
  const std::vector<NdtGrid>& fine = matcher.precision_layers();
  EXPECT_TRUE(fine[0].origin().isApprox(last.origin()));
  EXPECT_TRUE((last.origin() - fine[1].origin()).isApprox(Eigen::Vector3d::Constant(0.5 * half)));
  EXPECT_GE(static_cast<double>(fine[0].modelled_points()),
            0.8 * static_cast<double>(last.modelled_points()));

  // The floor: min_cell above half the edge sets the edge; above the last layer's edge, the last
  // layer's edge is used.
  s.precision.min_cell = 3.0;
  MlndtMatcher floor3(s);
  floor3.set_reference(reference);
  EXPECT_EQ(edges(floor3), (std::vector<double>{3.0, 3.0}));
  s.precision.min_cell = 50.0;
  MlndtMatcher floor50(s);
  floor50.set_reference(reference);
  EXPECT_EQ(edges(floor50), (std::vector<double>{last.cell_edge(), last.cell_edge()}));
  // The coverage rule: the finer cells model less than everything the last layer models (sparse
  // ground cells fall under min_points), so asking for all of it keeps the last layer's edge, whose
  // aligned grid has exactly the last layer's cells.
  s.precision.min_cell = 1.0;
  s.precision.min_coverage = 1.0;
  MlndtMatcher strict(s);
  strict.set_reference(reference);
  EXPECT_EQ(edges(strict), (std::vector<double>{last.cell_edge(), last.cell_edge()}));
  EXPECT_EQ(strict.precision_layers()[0].modelled_points(), last.modelled_points());
  s.precision.min_cell = 0.0;  // off
  MlndtMatcher off(s);
  off.set_reference(reference);
  EXPECT_TRUE(off.precision_layers().empty());
}

/// The median information along z (C'⁻¹ zz) of a grid's ground cells (means within 5 cm of z = 0).
double median_ground_information(const NdtGrid& grid) {
  std::vector<double> zz;
  for (int g = 0; g < static_cast<int>(grid.gaussian_count()); ++g)
    if (std::abs(grid.gaussian(g).mean[2]) < 0.05f) zz.push_back(grid.gaussian(g).inv_cov[5]);
  if (zz.empty()) return 0.0;
  std::nth_element(zz.begin(), zz.begin() + static_cast<std::ptrdiff_t>(zz.size() / 2), zz.end());
  return zz[zz.size() / 2];
}

// The precision grids raise eigenvalues only to λmax / 10⁴: a ground cell's Gaussian is as thin as
// the ground's 2 cm noise (information 1 / 0.02² = 2500 along z; more in a cell of about ten points,
// whose smallest sample spread falls short of the true one), where the layers' λmax / 100 makes it
// about ten times thicker (a 2.2 m cell: λmax ≈ 2.2² / 12, raised λ ≈ 0.004).
TEST(PrecisionStage, GridsKeepTheSurfacesThin) {
  const PointCloud reference = site(1);
  MlndtSettings s;
  ASSERT_DOUBLE_EQ(s.precision.max_eigen_ratio, 1e4);
  MlndtMatcher matcher(s);
  matcher.set_reference(reference);
  s.precision.max_eigen_ratio = 100.0;  // the layers' own
  MlndtMatcher thick(s);
  thick.set_reference(reference);
  ASSERT_EQ(matcher.precision_layers().size(), 2u);
  ASSERT_EQ(thick.precision_layers().size(), 2u);
  // The aligned grid (the pyramid's layer n + 1) and the shifted one.
  for (std::size_t i = 0; i < 2; ++i) {
    const double thin_zz = median_ground_information(matcher.precision_layers()[i]),
                 thick_zz = median_ground_information(thick.precision_layers()[i]);
    EXPECT_GT(thin_zz, 2000.0) << "grid " << i;
    EXPECT_LT(thin_zz, 5000.0) << "grid " << i;
    EXPECT_LT(thick_zz, 400.0) << "grid " << i;
  }
  EXPECT_LT(median_ground_information(matcher.layers().back()), 400.0);
}

TEST(PrecisionStage, RefinesTheLastLayersPoseOnALargeScene) {
  const PointCloud reference = site(2);
  // The input: a fresh sampling of the same site, GBS-sampled as odometry does, seen from T.
  const PointCloud scene = site(3);
  Rng pick(5);
  const PointCloud sampled = scene.subset(GridSampler(GridSamplerSettings{1.0, 5, 3}).select(scene, pick));
  const Eigen::Isometry3d T =
      to_isometry(Pose6{1.4, -0.6, 0.05, 0.3 * kRadPerDeg, -0.2 * kRadPerDeg, 2.0 * kRadPerDeg});
  const PointCloud input = sampled.transformed(T.inverse());
  const Eigen::Isometry3d guess = to_isometry(Pose6{1.2, -0.4, 0.0, 0.0, 0.0, 1.5 * kRadPerDeg});

  const auto run = [&](double min_cell) {
    MlndtSettings s;
    s.precision.min_cell = min_cell;
    MlndtMatcher m(s);
    m.set_reference(reference);
    return m.align(input, guess);
  };
  const RegistrationResult coarse = run(0.0), fine = run(1.0);
  ASSERT_TRUE(coarse.converged) << coarse.summary();
  ASSERT_TRUE(fine.converged) << fine.summary();
  EXPECT_EQ(fine.trace.back().layer, 5);  // the precision stage ran (labelled n + 1)
  EXPECT_EQ(coarse.trace.back().layer, 4);
  // Measured: the last layer alone 6.4 mm / 0.0036°, with the precision stage 4.8 mm / 0.0004°.
  EXPECT_LT(test::translation_error(fine.T, T), 0.9 * test::translation_error(coarse.T, T));
  EXPECT_LT(test::rotation_error_deg(fine.T, T), 0.3 * test::rotation_error_deg(coarse.T, T));
  EXPECT_LT(test::translation_error(fine.T, T), 0.006);
}

TEST(PrecisionStage, SettingsAreReadAndChecked) {
  const MlndtSettings thesis = read_mlndt_settings(YAML::Load("{preset: thesis}"), "x");
  EXPECT_FALSE(thesis.precision.enabled());
  const MlndtSettings on =
      read_mlndt_settings(YAML::Load("{precision_min_cell: 2, precision_min_coverage: 0.5}"), "x");
  EXPECT_DOUBLE_EQ(on.precision.min_cell, 2.0);
  EXPECT_DOUBLE_EQ(on.precision.min_coverage, 0.5);
  EXPECT_DOUBLE_EQ(on.precision.max_eigen_ratio, 1e4);
  EXPECT_DOUBLE_EQ(
      read_mlndt_settings(YAML::Load("{precision_max_eigen_ratio: 500}"), "x").precision.max_eigen_ratio,
      500.0);
  for (const char* bad :
       {"{precision_min_cell: -1}", "{precision_min_cell: 0.01}", "{precision_min_cell: 500}",
        "{precision_min_cell: .nan}", "{precision_min_coverage: 0}", "{precision_min_coverage: 1.5}",
        "{precision_min_cell: x}", "{precision_max_eigen_ratio: 0.5}", "{precision_max_eigen_ratio: .nan}",
        "{precision_max_eigen_ratio: .inf}"})
    EXPECT_THROW(read_mlndt_settings(YAML::Load(bad), "x"), InputError) << bad;
  PrecisionSettings p;
  std::string why;
  p.min_cell = 0.04;
  EXPECT_FALSE(p.valid(&why));
  EXPECT_NE(why.find("precision_min_cell"), std::string::npos);
  p.min_cell = 0.0;
  EXPECT_TRUE(p.valid(&why));
}

/// A 40 × 40 m floor and four 8 m walls, every surface a square grid of points `spacing` apart.
PointCloud gridded_room(double spacing) {
  PointCloud cloud;
  const int n = static_cast<int>(std::lround(40.0 / spacing)),
            h = static_cast<int>(std::lround(8.0 / spacing));
  for (int i = 0; i < n; ++i) {
    const auto a = static_cast<float>(i * spacing);
    for (int j = 0; j < n; ++j) cloud.push_back({a, static_cast<float>(j * spacing), 0.0f});
    for (int k = 1; k <= h; ++k) {
      const auto z = static_cast<float>(k * spacing);
      cloud.push_back({a, 0.0f, z});
      cloud.push_back({a, 40.0f, z});
      cloud.push_back({0.0f, a, z});
      cloud.push_back({40.0f, a, z});
    }
  }
  return cloud;
}

TEST(PrecisionStage, TheFloorFollowsThePointSpacing) {
  const double spacing = 0.25;
  const PointCloud room = gridded_room(spacing);
  MlndtSettings fine;  // no metric floor: the precision edge is layer n + 1's, half the last layer's
  fine.precision.min_cell = 0.05;
  MlndtMatcher plain(fine);
  plain.set_reference(room);
  ASSERT_FALSE(plain.precision_layers().empty());
  const double last_edge = 2.0 * plain.precision_layers()[0].cell_edge();
  // k · s between half the last layer's edge and the whole of it becomes the edge.
  MlndtSettings by_spacing = fine;
  by_spacing.precision.spacing_cells = 0.75 * last_edge / spacing;
  MlndtMatcher measured(by_spacing);
  measured.set_reference(room);
  ASSERT_FALSE(measured.precision_layers().empty());
  EXPECT_NEAR(measured.precision_layers()[0].cell_edge(), 0.75 * last_edge, 1e-6 * last_edge);
  // Below the metric floor it changes nothing; above the last layer's edge the stage takes that edge.
  by_spacing.precision.min_cell = 0.9 * last_edge;
  by_spacing.precision.spacing_cells = 1.0;
  MlndtMatcher floored(by_spacing);
  floored.set_reference(room);
  EXPECT_NEAR(floored.precision_layers()[0].cell_edge(), 0.9 * last_edge, 1e-6 * last_edge);
  by_spacing.precision.min_cell = 0.05;
  by_spacing.precision.spacing_cells = 2.0 * last_edge / spacing;
  MlndtMatcher coarse(by_spacing);
  coarse.set_reference(room);
  EXPECT_NEAR(coarse.precision_layers()[0].cell_edge(), last_edge, 1e-6 * last_edge);
  EXPECT_DOUBLE_EQ(
      read_mlndt_settings(YAML::Load("{precision_spacing_cells: 8}"), "x").precision.spacing_cells, 8.0);
  for (const char* bad : {"{precision_spacing_cells: 0.5}", "{precision_spacing_cells: -1}",
                          "{precision_spacing_cells: .nan}", "{precision_spacing_cells: 5000}"})
    EXPECT_THROW(read_mlndt_settings(YAML::Load(bad), "x"), InputError) << bad;
}

}  // namespace
}  // namespace sextant
