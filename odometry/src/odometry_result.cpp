// What a run's scans are as it registers them, and the counts of its result (odometry.hpp).
#include <algorithm>
#include <vector>

#include "sextant/odometry/odometry.hpp"

namespace sextant {

PointCloud load_sequence_scan(const Dataset& dataset, std::size_t i, double min_range,
                              ScanLoadReport* report) {
  PointCloud scan = dataset.scan(i, report);
  if (!(min_range > 0.0)) return scan;
  const float squared = static_cast<float>(min_range * min_range);
  std::vector<std::size_t> keep;
  keep.reserve(scan.size());
  for (std::size_t j = 0; j < scan.size(); ++j)
    if (scan[j].squaredNorm() >= squared) keep.push_back(j);
  return scan.subset(keep);
}

ScanLoadReport OdometryResult::dropped_total() const {
  ScanLoadReport total;
  for (const ScanLoadReport& load : loads) {
    total.points_read += load.points_read;
    total.non_finite_dropped += load.non_finite_dropped;
    total.no_return_dropped += load.no_return_dropped;
  }
  return total;
}

std::size_t OdometryResult::untrusted() const {
  return static_cast<std::size_t>(
      std::count_if(steps.begin(), steps.end(), [](const OdometryStep& s) { return !s.trusted(); }));
}

std::size_t OdometryResult::recovered() const {
  return static_cast<std::size_t>(
      std::count_if(steps.begin(), steps.end(), [](const OdometryStep& s) { return s.recovered(); }));
}

PointCloud registered_scan(const Dataset& dataset, const OdometryResult& result, std::size_t first,
                           std::size_t i, double min_range) {
  PointCloud scan = load_sequence_scan(dataset, first + i, min_range);
  return i < result.sweeps.size() ? deskew_scan(scan, result.sweeps[i]) : scan;
}

std::size_t OdometryResult::deskewed() const {
  return static_cast<std::size_t>(
      std::count_if(sweeps.begin(), sweeps.end(), [](const SweepMotion& s) { return s.known(); }));
}

}  // namespace sextant
