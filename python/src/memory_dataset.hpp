#pragma once
// A Dataset (core/dataset.hpp) over clouds held in memory, for sextant.odometry() on a list of
// arrays: optional ground truth, odometry and times, one per scan. Read-only after construction, so
// run_odometry may call scan() from several threads.
#include <optional>
#include <vector>

#include "sextant/core/dataset.hpp"

namespace sextant::python {

class MemoryDataset final : public Dataset {
 public:
  /// ValueError (std::invalid_argument) when a non-empty pose or time list does not have one entry
  /// per scan. `loads`: what reading each scan dropped, for those read from a file (or empty).
  MemoryDataset(std::vector<PointCloud> scans, std::vector<ScanLoadReport> loads,
                std::vector<Eigen::Isometry3d> ground_truth, std::vector<Eigen::Isometry3d> odometry,
                std::vector<double> times);

  const DatasetMetadata& metadata() const override { return meta_; }
  PointCloud scan(std::size_t i, ScanLoadReport* report) const override;
  std::optional<Eigen::Isometry3d> odometry(std::size_t i) const override;
  std::optional<Eigen::Isometry3d> ground_truth(std::size_t i) const override;
  std::optional<double> stamp(std::size_t i) const override;

 private:
  DatasetMetadata meta_;
  std::vector<PointCloud> scans_;
  std::vector<ScanLoadReport> loads_;
  std::vector<Eigen::Isometry3d> ground_truth_, odometry_;
  std::vector<double> times_;
};

}  // namespace sextant::python
