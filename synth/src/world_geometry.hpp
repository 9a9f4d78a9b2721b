#pragma once
// Small helpers of the world builder: its layout constants, lot rectangles, a building's local frame,
// the ground mesh (world_ground.cpp).
#include <cmath>

#include <Eigen/Core>

#include "sextant/core/rng.hpp"
#include "sextant/synth/settings.hpp"
#include "sextant/synth/world.hpp"

namespace sextant::synth::detail {

constexpr double kSidewalk = 3.0;            ///< lots start this far behind the kerb [m]
constexpr double kCrossingClearance = 14.0;  ///< no roadside objects this close to a crossing [m]

enum class RoofType { kFlat, kShed, kGabled };

/// An axis-aligned rectangle in the ground plane [m].
struct Rect {
  double x0, y0, x1, y1;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

/// A building's local frame: origin and yaw in the world.
struct LocalFrame {
  Eigen::Vector2d origin;
  double yaw = 0.0;
  Eigen::Vector3d to_world(double x, double y, double z) const {
    const double c = std::cos(yaw), s = std::sin(yaw);
    return {origin.x() + c * x - s * y, origin.y() + s * x + c * y, z};
  }
};

/// Fills world's ground grid (cell, size, heights) over [min, max] and adds its triangles.
void build_ground(const WorldSettings& s, Rng& rng, World& world);

}  // namespace sextant::synth::detail
