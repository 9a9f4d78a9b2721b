#include "sextant/core/io/trajectory_io.hpp"

#include <cmath>
#include <string>

#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/kitti.hpp"
#include "text_parse.hpp"

namespace sextant {

Trajectory read_tum_trajectory(const std::filesystem::path& file) {
  const std::string text = detail::read_file_bytes(file);
  Trajectory trajectory;
  std::vector<double> v;
  std::string bad;
  detail::for_each_line(text, [&](std::string_view line, long number) {
    if (detail::is_blank(line) || line.front() == '#') return;
    if (!detail::parse_numbers(line, v, &bad)) {
      throw InputError(file.string(), at_line(number), detail::bad_number_problem(bad));
    }
    if (v.size() != 8) {
      throw InputError(
          file.string(), at_line(number),
          "expected 8 numbers (timestamp tx ty tz qx qy qz qw), found " + std::to_string(v.size()));
    }
    for (double x : v) {
      if (!std::isfinite(x)) throw InputError(file.string(), at_line(number), "non-finite value");
    }
    const Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);  // Eigen's constructor takes w first
    if (std::abs(q.norm() - 1.0) > 1e-3) {
      throw InputError(file.string(), at_line(number),
                       "quaternion norm " + std::to_string(q.norm()) + " is not 1 (expected qx qy qz qw)");
    }
    StampedPose pose;
    pose.stamp = v[0];
    pose.pose.linear() = q.normalized().toRotationMatrix();
    pose.pose.translation() = Eigen::Vector3d(v[1], v[2], v[3]);
    trajectory.push_back(pose);
  });
  return trajectory;
}

void write_tum_trajectory(const std::filesystem::path& file, const Trajectory& trajectory) {
  std::string text;
  char stamp[64];
  for (const StampedPose& p : trajectory) {
    std::snprintf(stamp, sizeof stamp, "%.9f", p.stamp);
    text += stamp;
    const Eigen::Vector3d t = p.pose.translation();
    const Eigen::Quaterniond q(p.pose.linear());
    for (double x : {t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w()}) {
      text += ' ';
      detail::append_number(text, x);
    }
    text += '\n';
  }
  write_file_atomically(file, text);
}

Trajectory read_kitti_trajectory(const std::filesystem::path& file) {
  Trajectory trajectory;
  for (const Eigen::Isometry3d& pose : read_kitti_poses(file)) {
    trajectory.push_back({static_cast<double>(trajectory.size()), pose});
  }
  return trajectory;
}

void write_kitti_trajectory(const std::filesystem::path& file, const Trajectory& trajectory) {
  std::vector<Eigen::Isometry3d> poses;
  poses.reserve(trajectory.size());
  for (const StampedPose& p : trajectory) poses.push_back(p.pose);
  write_kitti_poses(file, poses);
}

TrajectoryFormat detect_trajectory_format(const std::filesystem::path& file) {
  const std::string text = detail::read_file_bytes(file);
  std::vector<double> v;
  std::string bad;
  long first_line = 0;
  std::size_t count = 0;
  detail::for_each_line(text, [&](std::string_view line, long number) {
    if (first_line != 0 || detail::is_blank(line) || line.front() == '#') return;
    if (!detail::parse_numbers(line, v, &bad))
      throw InputError(file.string(), at_line(number), detail::bad_number_problem(bad));
    first_line = number;
    count = v.size();
  });
  if (first_line == 0) throw InputError(file.string(), "", "no poses (an empty trajectory file)");
  if (count == 8) return TrajectoryFormat::kTum;
  if (count == 12) return TrajectoryFormat::kKitti;
  throw InputError(file.string(), at_line(first_line),
                   "expected a TUM line (8 numbers: timestamp tx ty tz qx qy qz qw) or a KITTI line (12 "
                   "numbers: a 3×4 row-major matrix), found " +
                       std::to_string(count) + " numbers");
}

Trajectory read_trajectory(const std::filesystem::path& file) {
  return detect_trajectory_format(file) == TrajectoryFormat::kTum ? read_tum_trajectory(file)
                                                                  : read_kitti_trajectory(file);
}

}  // namespace sextant
