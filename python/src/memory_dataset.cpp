// The in-memory Dataset of sextant.odometry() (memory_dataset.hpp).
#include "memory_dataset.hpp"

#include <stdexcept>
#include <string>

namespace sextant::python {
namespace {

template <class T>
void check_count(const std::vector<T>& values, std::size_t scans, const std::string& what) {
  if (!values.empty() && values.size() != scans)
    throw std::invalid_argument(what + ": " + std::to_string(values.size()) + " entries for " +
                                std::to_string(scans) + " scans (one per scan is expected)");
}

}  // namespace

MemoryDataset::MemoryDataset(std::vector<PointCloud> scans, std::vector<ScanLoadReport> loads,
                             std::vector<Eigen::Isometry3d> ground_truth,
                             std::vector<Eigen::Isometry3d> odometry, std::vector<double> times)
    : scans_(std::move(scans)),
      loads_(std::move(loads)),
      ground_truth_(std::move(ground_truth)),
      odometry_(std::move(odometry)),
      times_(std::move(times)) {
  check_count(ground_truth_, scans_.size(), "poses");
  check_count(odometry_, scans_.size(), "odometry_poses");
  check_count(times_, scans_.size(), "times");
  check_count(loads_, scans_.size(), "loads");
  meta_.name = "arrays";
  meta_.format = "arrays";
  meta_.scan_count = scans_.size();
  meta_.has_ground_truth = !ground_truth_.empty();
  meta_.has_odometry = !odometry_.empty();
}

PointCloud MemoryDataset::scan(std::size_t i, ScanLoadReport* report) const {
  const PointCloud& cloud = scans_.at(i);
  if (report) {
    *report = loads_.empty() ? ScanLoadReport{} : loads_.at(i);
    if (report->points_read == 0) report->points_read = cloud.size();  // an array: every row is kept
  }
  return cloud;
}

std::optional<Eigen::Isometry3d> MemoryDataset::odometry(std::size_t i) const {
  if (odometry_.empty()) return std::nullopt;
  return odometry_.at(i);
}

std::optional<Eigen::Isometry3d> MemoryDataset::ground_truth(std::size_t i) const {
  if (ground_truth_.empty()) return std::nullopt;
  return ground_truth_.at(i);
}

std::optional<double> MemoryDataset::stamp(std::size_t i) const {
  if (times_.empty()) return std::nullopt;
  return times_.at(i);
}

}  // namespace sextant::python
