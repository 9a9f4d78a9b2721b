#include "sextant/core/trajectory.hpp"

#include "sextant/core/pose.hpp"

namespace sextant {

std::vector<Eigen::Isometry3d> consecutive_motions(const Trajectory& trajectory) {
  std::vector<Eigen::Isometry3d> motions;
  for (std::size_t i = 1; i < trajectory.size(); ++i) {
    motions.push_back(relative(trajectory[i - 1].pose, trajectory[i].pose));
  }
  return motions;
}

}  // namespace sextant
