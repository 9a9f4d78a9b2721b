#pragma once
// Ray-castable primitives of the synthetic world.
#include <optional>

#include <Eigen/Core>

namespace sextant::synth {

struct Ray {
  Eigen::Vector3d origin;
  Eigen::Vector3d direction;  ///< unit length
};

/// An axis-aligned box [min, max].
struct Box {
  Eigen::Vector3d min, max;
  /// Distance along the ray to the first hit in [0, max_range], if any (slab method).
  std::optional<double> intersect(const Ray& ray, double max_range) const;
};

}  // namespace sextant::synth
