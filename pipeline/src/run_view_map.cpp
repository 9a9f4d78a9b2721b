// The run's map as its view draws it (odometry_view.hpp): coarser voxels until few enough points.
#include "sextant/pipeline/odometry_view.hpp"

namespace sextant {

RunViewMap run_view_map(const RunMap& map, std::size_t max_points) {
  RunViewMap out;
  out.points = map.cloud();
  out.voxel = map.voxel_size();
  out.scans_read = map.scans();
  while (out.points.size() > std::max<std::size_t>(1, max_points)) {
    out.voxel *= 2.0;
    RunMap coarser(out.voxel);
    coarser.add(out.points, Eigen::Isometry3d::Identity());
    out.points = coarser.cloud();
  }
  return out;
}

}  // namespace sextant
