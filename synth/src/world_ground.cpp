// The campus ground: a gently rolling height field on a regular grid, meshed into triangles.
#include <cmath>
#include <cstddef>

#include "sextant/core/units.hpp"
#include "world_geometry.hpp"

namespace sextant::synth::detail {

void build_ground(const WorldSettings& s, Rng& rng, World& world) {
  const double phase1 = rng.uniform(0, 2 * kPi), phase2 = rng.uniform(0, 2 * kPi),
               phase3 = rng.uniform(0, 2 * kPi), tilt_dir = rng.uniform(0, 2 * kPi);
  const double k = 2 * kPi / s.ground_wavelength;
  const auto height = [&](double x, double y) {
    return s.ground_tilt * (std::cos(tilt_dir) * x + std::sin(tilt_dir) * y) +
           s.ground_amplitude * std::sin(k * x + phase1) * std::cos(1.3 * k * y + phase2) +
           0.3 * s.ground_amplitude * std::sin(2.1 * k * (x + 0.7 * y) + phase3);
  };
  world.ground_cell = s.ground_cell;
  world.ground_nx = static_cast<int>(std::ceil((world.max.x() - world.min.x()) / s.ground_cell)) + 1;
  world.ground_ny = static_cast<int>(std::ceil((world.max.y() - world.min.y()) / s.ground_cell)) + 1;
  const auto vertex = [&](int i, int j) {
    const double x = world.min.x() + i * s.ground_cell, y = world.min.y() + j * s.ground_cell;
    return Eigen::Vector3d(x, y, world.ground_heights[static_cast<std::size_t>(j) * world.ground_nx + i]);
  };
  for (int j = 0; j < world.ground_ny; ++j)
    for (int i = 0; i < world.ground_nx; ++i)
      world.ground_heights.push_back(
          height(world.min.x() + i * s.ground_cell, world.min.y() + j * s.ground_cell));
  const auto add = [&](const Triangle& t) {
    world.primitives.push_back(Primitive{t, ObjectKind::kGround, -1});
  };
  for (int j = 0; j + 1 < world.ground_ny; ++j) {
    for (int i = 0; i + 1 < world.ground_nx; ++i) {
      // Split along (0,0)–(1,1), matching World::ground_height.
      add(Triangle{vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
      add(Triangle{vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
    }
  }
}

}  // namespace sextant::synth::detail
