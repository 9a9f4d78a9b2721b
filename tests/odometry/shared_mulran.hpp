#pragma once
// The shared MulRan Riverside02 excerpt, for the real-sequence tests (they skip when it is absent), and
// what they judge with: the reference's slip, the trusted steps expected right, folders of keyframes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sextant/core/dataset.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/io/kitti.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/vehicle_slip.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant_test/temp_dir.hpp"

namespace sextant::test {

/// ../shared/data/mulran_riverside02 beside the repository.
inline const std::filesystem::path kMulran =
    std::filesystem::path(SEXTANT_SHARED_DATA_DIR) / "mulran_riverside02";

/// A reference step that slips sideways more than this cannot judge a step at the 1 m bar (a car
/// follows arcs: vehicle_slip.hpp) [m].
inline constexpr double kReferenceSlip = 0.5;

/// The reference's relative motions of scans first, first + 1, … first + steps and their slip.
inline VehicleSlip reference_slip(const Dataset& dataset, std::size_t first, std::size_t steps) {
  std::vector<Eigen::Isometry3d> poses;
  for (std::size_t i = first; i <= first + steps; ++i) poses.push_back(*dataset.ground_truth(i));
  return vehicle_slip(poses);
}

/// The trusted steps of `r` (scans first, first + 1, …), each expected within 1 m and 5° of the
/// reference's relative motion where the reference is a car's path; `unjudged` counts the trusted
/// steps where it is not (its slip above kReferenceSlip).
inline std::size_t trusted_steps_expecting_them_right(const Dataset& dataset, const OdometryResult& r,
                                                      std::size_t first, std::size_t* unjudged = nullptr) {
  const VehicleSlip slip = reference_slip(dataset, first, r.steps.size());
  std::size_t trusted = 0;
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    if (!r.steps[i].trusted()) continue;
    ++trusted;
    if (std::abs(slip.slip[i]) > kReferenceSlip) {
      if (unjudged) ++*unjudged;
      continue;
    }
    const Eigen::Isometry3d truth =
        relative(*dataset.ground_truth(first + i), *dataset.ground_truth(first + i + 1));
    const Eigen::Isometry3d error = relative(truth, r.steps[i].relative);
    const bool wrong = translation_norm(error) > 1.0 || rotation_angle(error) * kDegPerRad > 5.0;
    EXPECT_FALSE(wrong) << "step " << first + i << " is " << translation_norm(error)
                        << " m off and says trusted";
  }
  return trusted;
}

/// The MulRan keyframes `keyframes`, in that order, as a folder dataset in `folder`: links to the
/// shared scans, their rows of poses.txt and, `with_times`, of times.txt.
inline std::unique_ptr<Dataset> mulran_excerpt(const std::filesystem::path& folder,
                                               const std::vector<std::size_t>& keyframes, bool with_times) {
  const auto lines_of = [](const std::filesystem::path& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  };
  const auto six_digits = [](std::size_t k) {
    return std::string(6 - std::to_string(k).size(), '0') + std::to_string(k);
  };
  const std::vector<std::string> all_poses = lines_of(kMulran / "poses.txt"),
                                 all_times = lines_of(kMulran / "times.txt");
  std::filesystem::create_directories(folder / "scans");
  std::string poses, times;
  for (std::size_t n = 0; n < keyframes.size(); ++n) {
    const std::size_t i = keyframes[n];
    std::filesystem::create_symlink(kMulran / "scans" / (six_digits(i) + ".pcd"),
                                    folder / "scans" / (six_digits(n) + ".pcd"));
    poses += all_poses.at(i) + "\n";
    times += all_times.at(i) + "\n";
  }
  write_text(folder / "poses.txt", poses);
  if (with_times) test::write_text(folder / "times.txt", times);
  return open_dataset(folder);
}

/// The MulRan keyframes `keyframes` as another set-up would record them, a folder dataset with poses and
/// times in `folder`: keyframe n's points `made(scan, n)`, in the frame `frame(n)` moves them to (the
/// scan's coordinates as written ← the recording sensor's), its pose the reference's moved with them.
inline std::unique_ptr<Dataset> mulran_made_into(
    const std::filesystem::path& folder, const std::vector<std::size_t>& keyframes,
    const std::function<PointCloud(const PointCloud&, std::size_t)>& made,
    const std::function<Eigen::Isometry3d(std::size_t)>& frame) {
  const auto linked = mulran_excerpt(folder / "links", keyframes, true);
  std::filesystem::create_directories(folder / "scans");
  std::vector<Eigen::Isometry3d> poses;
  for (std::size_t n = 0; n < keyframes.size(); ++n) {
    write_cloud(folder / "scans" / (std::to_string(100000 + n) + ".pcd"),
                made(linked->scan(n), n).transformed(frame(n)));
    poses.push_back(*linked->ground_truth(n) * frame(n).inverse());
  }
  write_kitti_poses(folder / "poses.txt", poses);
  std::filesystem::copy_file(folder / "links" / "times.txt", folder / "times.txt");
  return open_dataset(folder);
}

}  // namespace sextant::test
