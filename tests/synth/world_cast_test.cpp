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

}  // namespace
}  // namespace sextant::synth
