#include "sextant/core/io/trajectory_io.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/kitti.hpp"
#include "text_parse.hpp"

namespace sextant {

std::string trajectory_note(const std::filesystem::path& file, const TrajectoryReadNotes& notes) {
  if (notes.out_of_order == 0) return "";
  return file.string() + ": " + std::to_string(notes.out_of_order) +
         " poses come after a later stamp; the trajectory is taken in time order (sorted by stamp)";
}

Trajectory read_tum_trajectory(const std::filesystem::path& file, TrajectoryReadNotes* notes) {
  const std::string text = detail::read_file_bytes(file);
  Trajectory trajectory;
  std::vector<long> lines;  // the file line of each pose
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
    lines.push_back(number);
  });
  // Time order: a pose whose stamp is before the largest stamp so far is out of order.
  std::size_t out_of_order = 0;
  double latest = -std::numeric_limits<double>::infinity();
  for (const StampedPose& p : trajectory) {
    if (p.stamp < latest) ++out_of_order;
    latest = std::max(latest, p.stamp);
  }
  std::vector<std::size_t> order(trajectory.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return trajectory[a].stamp < trajectory[b].stamp; });
  for (std::size_t k = 1; k < order.size(); ++k)
    if (trajectory[order[k]].stamp == trajectory[order[k - 1]].stamp)
      throw InputError(file.string(), at_line(lines[order[k]]),
                       "the stamp " + std::to_string(trajectory[order[k]].stamp) +
                           " is given twice (also at line " + std::to_string(lines[order[k - 1]]) +
                           "): which pose holds then?");
  if (notes) notes->out_of_order = out_of_order;
  if (out_of_order == 0) return trajectory;
  Trajectory sorted;
  sorted.reserve(trajectory.size());
  for (std::size_t k : order) sorted.push_back(trajectory[k]);
  return sorted;
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

Trajectory read_trajectory(const std::filesystem::path& file, TrajectoryReadNotes* notes) {
  if (notes) *notes = TrajectoryReadNotes{};
  return detect_trajectory_format(file) == TrajectoryFormat::kTum ? read_tum_trajectory(file, notes)
                                                                  : read_kitti_trajectory(file);
}

}  // namespace sextant
