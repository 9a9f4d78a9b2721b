// World::cast walks the 2D primitive grid and skips primitives the ray passes over or under in
// the current cell: it must find exactly the first hit a test of every primitive finds.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <type_traits>
#include <variant>

#include "sextant/synth/campus.hpp"
#include "sextant/synth/world.hpp"

namespace sextant::synth {
namespace {

/// The first hit over every primitive, without the grid (foliage as solid: porosity and
/// penetration 0, so that its hit is the ellipsoid's entry).
std::optional<double> first_hit_of_all(const World& world, const Ray& ray, double max_range) {
  std::optional<double> best;
  for (const Primitive& p : world.primitives) {
    const std::optional<double> t = std::visit(
        [&](const auto& s) -> std::optional<double> {
          if constexpr (std::is_same_v<std::decay_t<decltype(s)>, Ellipsoid>) {
            const auto span = s.span(ray, max_range);
            return span ? std::optional<double>(span->entry) : std::nullopt;
          } else {
            return s.intersect(ray, max_range);
          }
        },
        p.shape);
    if (t && (!best || *t < *best)) best = t;
  }
  return best;
}

TEST(WorldCast, FindsTheSameFirstHitAsTestingEveryPrimitive) {
  const Campus campus = generate_campus(CampusSettings{}, 3);
  World world = *campus.world;
  world.foliage_porosity = 0.0;
  world.foliage_penetration = 0.0;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double pi = std::acos(-1.0);
  int hits = 0, rays_up = 0, compared = 0;
  for (int i = 0; i < 4000; ++i) {
    // Origins over the whole world (inside buildings too) at sensor heights and above the roofs;
    // directions from straight down to straight up.
    Ray ray;
    const double uz = unit(rng), uy = unit(rng), ux = unit(rng);  // z first, the order the data were made in
    ray.origin = Eigen::Vector3d(world.min.x() + ux * (world.max.x() - world.min.x()),
                                 world.min.y() + uy * (world.max.y() - world.min.y()), -1.0 + uz * 30.0);
    const double azimuth = 2.0 * pi * unit(rng), elevation = std::asin(2.0 * unit(rng) - 1.0);
    ray.direction = Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                    std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
    const double max_range = 120.0;
    const std::optional<double> expected = first_hit_of_all(world, ray, max_range);
    const std::optional<RayHit> got = world.cast(ray, max_range, static_cast<std::uint64_t>(i));
    ASSERT_EQ(expected.has_value(), got.has_value()) << "ray " << i;
    ++compared;
    if (ray.direction.z() > 0.0) ++rays_up;
    if (!got) continue;
    ++hits;
    EXPECT_EQ(*expected, got->range) << "ray " << i;
  }
  EXPECT_EQ(compared, 4000);
  EXPECT_GT(hits, 2000);     // most rays hit something: the comparison is not vacuous
  EXPECT_GT(rays_up, 1500);  // and many go up, past the ground of every cell they cross
}

// The grid lists a primitive in the cells its xy box overlaps, not in the cell its box only touches
// (the ground mesh's triangles end exactly on cell borders): rays that meet the ground exactly on a
// cell border or corner, from either side, still find it, where testing every primitive does.
TEST(WorldCast, FindsTheGroundOnCellBordersFromEitherSide) {
  const Campus campus = generate_campus(CampusSettings{}, 3);
  World world = *campus.world;
  world.foliage_porosity = 0.0;
  world.foliage_penetration = 0.0;
  const double cell = CampusSettings{}.world.grid_cell;
  ASSERT_EQ(cell, world.ground_cell);  // the mesh's vertices lie on the grid's borders
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int nx = static_cast<int>((world.max.x() - world.min.x()) / cell);
  const int ny = static_cast<int>((world.max.y() - world.min.y()) / cell);
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    // A target on a border: x on one (i % 3 == 0), y on one (1), or both, a corner (2).
    // 6 cells (24 m) in from the world's edge: the rays start inside the grid.
    const int bx = 6 + static_cast<int>(unit(rng) * (nx - 12)),
              by = 6 + static_cast<int>(unit(rng) * (ny - 12));
    double x = world.min.x() + (bx + unit(rng)) * cell, y = world.min.y() + (by + unit(rng)) * cell;
    if (i % 3 != 1) x = world.min.x() + bx * cell;
    if (i % 3 != 0) y = world.min.y() + by * cell;
    const Eigen::Vector3d target(x, y, world.ground_height(x, y));
    // From 2–20 m away on either side, 1.5–3 m above the ground.
    const double angle = 2.0 * std::acos(-1.0) * unit(rng), reach = 2.0 + 18.0 * unit(rng);
    Ray ray;
    ray.origin =
        target + Eigen::Vector3d(reach * std::cos(angle), reach * std::sin(angle), 1.5 + 1.5 * unit(rng));
    ray.direction = (target - ray.origin).normalized();
    const std::optional<double> expected = first_hit_of_all(world, ray, 120.0);
    const std::optional<RayHit> got = world.cast(ray, 120.0, static_cast<std::uint64_t>(i));
    ASSERT_EQ(expected.has_value(), got.has_value()) << "ray " << i;
    if (!got) continue;
    // Two triangles of the mesh meet on the border: either may be found, their ranges a few ulps apart.
    EXPECT_NEAR(*expected, got->range, 1e-12 * got->range) << "ray " << i;
    if (std::abs(got->range - (target - ray.origin).norm()) < 1e-6) ++hits;
  }
  EXPECT_GT(hits, 1500);  // most rays reach their border point unobstructed: the borders are tested
}

}  // namespace
}  // namespace sextant::synth
