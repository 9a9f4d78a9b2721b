#pragma once
// The largest position error of a trajectory against its truth, for the tests of every module.
#include <algorithm>
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

namespace sextant::test {

/// max_k ‖t(estimate_k) − t(truth_k)‖ over the poses both have [m].
inline double worst_error(const std::vector<Eigen::Isometry3d>& estimate,
                          const std::vector<Eigen::Isometry3d>& truth) {
  double worst = 0.0;
  for (std::size_t k = 0; k < std::min(estimate.size(), truth.size()); ++k)
    worst = std::max(worst, (estimate[k].translation() - truth[k].translation()).norm());
  return worst;
}

}  // namespace sextant::test
