#include "sextant/synth/primitives.hpp"

#include <algorithm>
#include <limits>

namespace sextant::synth {

std::optional<double> Box::intersect(const Ray& ray, double max_range) const {
  double t_near = 0.0, t_far = max_range;
  for (int axis = 0; axis < 3; ++axis) {
    const double inv = 1.0 / ray.direction[axis];  // ±inf for axis-parallel rays
    double t0 = (min[axis] - ray.origin[axis]) * inv;
    double t1 = (max[axis] - ray.origin[axis]) * inv;
    if (t0 > t1) std::swap(t0, t1);
    t_near = std::max(t_near, t0);
    t_far = std::min(t_far, t1);
    if (t_near > t_far) return std::nullopt;
  }
  return t_near;
}

}  // namespace sextant::synth
