#include "kit/row_codec.hpp"

#include "sextant/core/units.hpp"

namespace sextant {

std::vector<double> isometry_to_series(const Eigen::Isometry3d& T) {
  std::vector<double> s;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) s.push_back(T.matrix()(r, c));
  }
  return s;
}

Eigen::Isometry3d series_to_isometry(const std::vector<double>& s) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c)
      T.matrix()(r, c) = s.size() == 12 ? s[static_cast<std::size_t>(4 * r + c)] : kNaN;
  }
  return T;
}

std::vector<double> poses_to_series(const PoseList& poses) {
  std::vector<double> s;
  for (const auto& T : poses) {
    const auto one = isometry_to_series(T);
    s.insert(s.end(), one.begin(), one.end());
  }
  return s;
}

PoseList series_to_poses(const std::vector<double>& series) {
  PoseList poses;
  for (std::size_t i = 0; i + 12 <= series.size(); i += 12)
    poses.push_back(series_to_isometry(std::vector<double>(series.begin() + i, series.begin() + i + 12)));
  return poses;
}

}  // namespace sextant
