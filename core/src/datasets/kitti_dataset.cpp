// A KITTI odometry sequence folder.
#include <stdexcept>

#include "listed_scans_dataset.hpp"
#include "scan_files.hpp"
#include "sextant/core/dataset.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/io/kitti.hpp"

namespace sextant {
namespace {

class KittiDataset final : public detail::ListedScansDataset {
 public:
  explicit KittiDataset(const std::filesystem::path& folder) {
    detail::ScanListing listing = detail::list_scans(folder / "velodyne", "", {".bin", ".xyz32.bin"});
    scans_ = std::move(listing.files);
    meta_.notes = std::move(listing.notes);
    if (scans_.empty()) {
      throw InputError((folder / "velodyne").string(), "",
                       "no NNNNNN.bin files (not a KITTI sequence folder)");
    }
    meta_.name = detail::folder_name(folder);
    meta_.format = "kitti";
    meta_.path = folder;
    meta_.scan_count = scans_.size();
    read_poses(folder);
    const auto times_file = folder / "times.txt";
    if (std::filesystem::exists(times_file)) {
      times_ = read_kitti_times(times_file);
      check_count(times_file, times_.size(), "times");
    }
    meta_.has_ground_truth = !ground_truth_.empty();
  }

 private:
  void read_poses(const std::filesystem::path& folder) {
    std::filesystem::path poses_file = folder / "poses.txt";
    if (!std::filesystem::exists(poses_file)) {
      poses_file = folder / ".." / ".." / "poses" / (meta_.name + ".txt");  // the benchmark's layout
      if (!std::filesystem::exists(poses_file)) return;
    }
    const auto calib_file = folder / "calib.txt";
    if (!std::filesystem::exists(calib_file)) {
      throw InputError(
          calib_file.string(), "",
          "missing: needed to turn " + poses_file.string() + " (camera 0) into Velodyne-frame poses");
    }
    const auto camera_poses = read_kitti_poses(poses_file);
    check_count(poses_file, camera_poses.size(), "poses");
    ground_truth_ = kitti_velodyne_poses(camera_poses, read_kitti_calib_tr(calib_file));
  }
};

}  // namespace

std::unique_ptr<Dataset> open_kitti_dataset(const std::filesystem::path& folder) {
  return std::make_unique<KittiDataset>(folder);
}

}  // namespace sextant
