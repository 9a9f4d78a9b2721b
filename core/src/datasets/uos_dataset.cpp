// A uos folder (hannover1 layout, and the built-in synthetic campus's output).
#include <stdexcept>

#include "scan_files.hpp"
#include "sextant/core/dataset.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/io/uos.hpp"

namespace sextant {
namespace {

/// Reads one pose per scan from the sibling file with `extension`; empty when no scan has one.
template <class ReadPose>
std::vector<Eigen::Isometry3d> read_sibling_poses(const std::vector<detail::NumberedFile>& scans,
                                                  const std::string& extension, const std::string& what,
                                                  ReadPose read_pose) {
  std::vector<std::filesystem::path> files;
  std::size_t present = 0;
  for (const auto& scan : scans) {
    files.push_back(std::filesystem::path(scan.path).replace_extension(extension));
    if (std::filesystem::exists(files.back())) ++present;
  }
  std::vector<Eigen::Isometry3d> poses;
  if (present == 0) return poses;
  for (const auto& file : files) {
    if (!std::filesystem::exists(file)) {
      throw InputError(file.string(), "",
                       "missing " + what + " file (" + std::to_string(present) + " of " +
                           std::to_string(files.size()) + " scans have one)");
    }
    poses.push_back(read_pose(file));
  }
  return poses;
}

class UosDataset final : public Dataset {
 public:
  explicit UosDataset(const std::filesystem::path& folder) {
    detail::ScanListing listing = detail::list_scans(folder, "scan", {".3d"});
    scans_ = std::move(listing.files);
    meta_.notes = std::move(listing.notes);
    if (scans_.empty()) throw InputError(folder.string(), "", "no scanNNN.3d files (not a uos folder)");
    odometry_ = read_sibling_poses(scans_, ".pose", "odometry (.pose)",
                                   [](const std::filesystem::path& f) { return read_uos_pose(f); });
    ground_truth_ =
        read_sibling_poses(scans_, ".frames", "registration (.frames)",
                           [](const std::filesystem::path& f) { return read_uos_frames(f).back(); });
    meta_.name = detail::folder_name(folder);
    meta_.format = "uos";
    meta_.path = folder;
    meta_.scan_count = scans_.size();
    meta_.has_odometry = !odometry_.empty();
    meta_.has_ground_truth = !ground_truth_.empty();
  }

  const DatasetMetadata& metadata() const override { return meta_; }

  PointCloud scan(std::size_t i, ScanLoadReport* report) const override {
    return read_cloud(scans_.at(i).path, report);
  }
  std::optional<Eigen::Isometry3d> odometry(std::size_t i) const override {
    return pose_or_none(odometry_, i);
  }
  std::optional<Eigen::Isometry3d> ground_truth(std::size_t i) const override {
    return pose_or_none(ground_truth_, i);
  }
  std::filesystem::path scan_file(std::size_t i) const override { return scans_.at(i).path; }

 private:
  std::optional<Eigen::Isometry3d> pose_or_none(const std::vector<Eigen::Isometry3d>& poses,
                                                std::size_t i) const {
    if (i >= scans_.size()) throw std::out_of_range("scan index " + std::to_string(i) + " out of range");
    if (poses.empty()) return std::nullopt;
    return poses[i];
  }

  DatasetMetadata meta_;
  std::vector<detail::NumberedFile> scans_;
  std::vector<Eigen::Isometry3d> odometry_, ground_truth_;
};

}  // namespace

std::unique_ptr<Dataset> open_uos_dataset(const std::filesystem::path& folder) {
  return std::make_unique<UosDataset>(folder);
}

}  // namespace sextant
