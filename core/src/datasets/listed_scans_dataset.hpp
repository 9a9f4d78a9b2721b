#pragma once
// Private: a dataset of listed scan files with optional ground truth and times and no odometry —
// the KITTI layout and any folder of scans share it; each fills the members in its constructor.
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "scan_files.hpp"
#include "sextant/core/dataset.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/cloud_io.hpp"

namespace sextant::detail {

class ListedScansDataset : public Dataset {
 public:
  const DatasetMetadata& metadata() const override { return meta_; }
  PointCloud scan(std::size_t i, ScanLoadReport* report) const override {
    return read_cloud(scans_.at(i).path, report);
  }
  std::optional<Eigen::Isometry3d> odometry(std::size_t i) const override {
    check_index(i);
    return std::nullopt;
  }
  std::optional<Eigen::Isometry3d> ground_truth(std::size_t i) const override {
    check_index(i);
    if (ground_truth_.empty()) return std::nullopt;
    return ground_truth_[i];
  }
  std::optional<double> stamp(std::size_t i) const override {
    check_index(i);
    if (times_.empty()) return std::nullopt;
    return times_[i];
  }
  std::filesystem::path scan_file(std::size_t i) const override { return scans_.at(i).path; }

 protected:
  /// InputError naming `file` when it holds `count` of `what` for a different number of scans.
  void check_count(const std::filesystem::path& file, std::size_t count, const std::string& what) const {
    if (count != scans_.size())
      throw InputError(file.string(), "",
                       std::to_string(count) + " " + what + " for " + std::to_string(scans_.size()) +
                           " scans (one per scan, in the scans' order, is expected)");
  }
  void check_index(std::size_t i) const {
    if (i >= scans_.size()) throw std::out_of_range("scan index " + std::to_string(i) + " out of range");
  }

  DatasetMetadata meta_;
  std::vector<NumberedFile> scans_;
  std::vector<Eigen::Isometry3d> ground_truth_;  ///< world ← scan, or empty
  std::vector<double> times_;                    ///< [s], or empty
};

}  // namespace sextant::detail
