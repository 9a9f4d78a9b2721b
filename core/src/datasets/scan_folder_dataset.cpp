// Any folder of point-cloud files as a dataset, and the layout detection of open_dataset.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "listed_scans_dataset.hpp"
#include "scan_files.hpp"
#include "sextant/core/dataset.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/io/kitti.hpp"
#include "sextant/core/io/trajectory_io.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;

/// The folder's scans, or those of folder/scans when the folder itself holds none. InputError when
/// both hold scans (which are the sequence?), or when neither does (naming the cloud files left out).
detail::ScanListing scan_listing(const fs::path& folder, fs::path& scans_folder) {
  scans_folder = folder;
  detail::ScanListing listing = detail::list_scans(folder, "", scan_folder_extensions());
  if (fs::is_directory(folder / "scans")) {
    detail::ScanListing inner = detail::list_scans(folder / "scans", "", scan_folder_extensions());
    if (!listing.files.empty() && !inner.files.empty())
      throw InputError(folder.string(), "",
                       "both the folder (" + std::to_string(listing.files.size()) +
                           " scans) and scans/ inside it (" + std::to_string(inner.files.size()) +
                           ") hold scans: which are the sequence? Give the folder that holds them alone");
    if (listing.files.empty()) {
      if (!listing.left_out.empty())
        inner.notes.push_back("in the folder itself: " + detail::left_out_note(listing.left_out));
      scans_folder = folder / "scans";
      listing = std::move(inner);
    }
  }
  if (listing.files.empty())
    throw InputError(
        folder.string(), "",
        "no scans: expected point-cloud files (.pcd .ply .bin .xyz32.bin .xyz .csv .3d) with a "
        "number in the name, in the folder or in scans/ inside it" +
            (listing.left_out.empty() ? std::string() : "; " + detail::left_out_note(listing.left_out)));
  return listing;
}

/// `name` in the scans' folder or, failing that, in `folder`; empty when in neither.
fs::path beside(const fs::path& folder, const fs::path& scans_folder, const std::string& name) {
  for (const fs::path& place : {scans_folder, folder})
    if (fs::exists(place / name)) return place / name;
  return {};
}

class ScanFolderDataset final : public detail::ListedScansDataset {
 private:
  /// A TUM file's poses pair with the scans by time: pose k (in time order) must be stamped with scan
  /// k's time, to within half the shortest time between two scans.
  void check_stamps(const fs::path& poses, const Trajectory& trajectory, const fs::path& times) const {
    double shortest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k < times_.size(); ++k) shortest = std::min(shortest, times_[k] - times_[k - 1]);
    const double tolerance = std::isfinite(shortest) ? 0.5 * shortest : 1e-3;
    for (std::size_t k = 0; k < trajectory.size(); ++k) {
      if (std::abs(trajectory[k].stamp - times_[k]) <= tolerance) continue;
      throw InputError(poses.string(), "",
                       "the poses pair with the scans by time, but the pose of scan " + std::to_string(k) +
                           " is stamped " + std::to_string(trajectory[k].stamp) +
                           " s and the scan's time is " + std::to_string(times_[k]) + " s (" +
                           times.string() + "), more than " + std::to_string(tolerance) +
                           " s apart: stamp the poses with the scans' times (or give them as KITTI poses, "
                           "one per scan in order)");
    }
  }

 public:
  ScanFolderDataset(const fs::path& folder, const fs::path& poses_file) {
    fs::path scans_folder;
    detail::ScanListing listing = scan_listing(folder, scans_folder);
    scans_ = std::move(listing.files);
    meta_.notes = std::move(listing.notes);
    meta_.name = detail::folder_name(folder);
    meta_.format = "folder";
    meta_.path = folder;
    meta_.scan_count = scans_.size();
    const fs::path times = beside(folder, scans_folder, "times.txt");
    if (!times.empty()) {
      times_ = read_kitti_times(times);
      check_count(times, times_.size(), "times");
    } else if (times_ = detail::times_in_names(scans_); !times_.empty()) {
      meta_.notes.push_back("the scans' times are the numbers in their names (" +
                            scans_.front().path.filename().string() + " is at " +
                            std::to_string(times_.front()) + " s); a times.txt would replace them");
    }
    const fs::path poses = poses_file.empty() ? beside(folder, scans_folder, "poses.txt") : poses_file;
    if (!poses.empty()) {
      TrajectoryReadNotes read;
      const bool stamped = !poses_file.empty() && detect_trajectory_format(poses) == TrajectoryFormat::kTum;
      const Trajectory trajectory =
          poses_file.empty() ? read_kitti_trajectory(poses) : read_trajectory(poses, &read);
      if (const std::string note = trajectory_note(poses, read); !note.empty()) meta_.notes.push_back(note);
      check_count(poses, trajectory.size(), "poses");
      if (stamped && !times_.empty()) check_stamps(poses, trajectory, times);
      for (const StampedPose& p : trajectory) ground_truth_.push_back(p.pose);
    }
    meta_.has_ground_truth = !ground_truth_.empty();
  }
};

}  // namespace

const std::vector<std::string>& scan_folder_extensions() {
  static const std::vector<std::string> extensions{".pcd", ".ply", ".bin", ".xyz32.bin",
                                                   ".xyz", ".csv", ".3d"};
  return extensions;
}

std::unique_ptr<Dataset> open_scan_folder(const fs::path& folder, const fs::path& poses_file) {
  if (!fs::is_directory(folder))
    throw FileError(folder.string(), "not a folder", fs::exists(folder) ? ENOTDIR : ENOENT);
  return std::make_unique<ScanFolderDataset>(folder, poses_file);
}

std::unique_ptr<Dataset> open_dataset(const fs::path& folder) {
  if (!fs::is_directory(folder))
    throw FileError(folder.string(), "not a folder", fs::exists(folder) ? ENOTDIR : ENOENT);
  if (fs::is_directory(folder / "velodyne")) return open_kitti_dataset(folder);
  if (!detail::list_scans(folder, "scan", {".3d"}).files.empty()) return open_uos_dataset(folder);
  return open_scan_folder(folder);
}

}  // namespace sextant
