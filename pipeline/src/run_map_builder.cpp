#include "sextant/pipeline/run_map_builder.hpp"

#include <sstream>
#include <stdexcept>
#include <utility>

#include "sextant/core/error.hpp"
#include "sextant/odometry/deskew.hpp"

namespace sextant {

std::string RunMapSummary::voxel_origin() const {
  if (!default_voxel) return "given";
  std::ostringstream text;
  text.precision(3);
  text << "1/100 of the first scan's median range, " << median_range << " m";
  return text.str();
}

RunMapBuilder::RunMapBuilder(RunMapSettings settings) : settings_(std::move(settings)) {
  if (settings_.voxel) map_.emplace(*settings_.voxel);  // checks it
}

void RunMapBuilder::add(const RegisteredScan& scan) {
  if (!seen_first_) {
    seen_first_ = true;
    median_range_ = scan_median_range(*scan.scan);
    if (!settings_.voxel) map_.emplace(default_map_voxel_size(*scan.scan));
  }
  if (settings_.trusted_only && scan.step && !scan.step->trusted()) {
    ++left_out_;
    return;
  }
  map_->add(*scan.scan, scan.world_from_scan);
}

OdometryScanObserver RunMapBuilder::observer() {
  return [this](const RegisteredScan& scan) { add(scan); };
}

const RunMap& RunMapBuilder::map() const {
  if (!map_) throw std::logic_error("RunMapBuilder::map() before any scan");
  return *map_;
}

RunMapSummary RunMapBuilder::summary() const {
  RunMapSummary s;
  s.default_voxel = !settings_.voxel;
  s.median_range = median_range_;
  s.scans_left_out = left_out_;
  if (map_) {
    s.voxel = map_->voxel_size();
    s.points = map_->size();
    s.scans = map_->scans();
    s.skipped_points = map_->skipped_points();
    s.intensity = map_->has_intensity();
  }
  return s;
}

RunMapBuilder build_run_map(const Dataset& dataset, std::size_t first,
                            const std::vector<Eigen::Isometry3d>& poses,
                            const std::vector<OdometryStep>& steps, double min_range,
                            const RunMapSettings& settings, const std::vector<SweepMotion>& sweeps) {
  if (poses.empty() || steps.size() + 1 != poses.size())
    throw InputError("map", "",
                     std::to_string(poses.size()) + " poses and " + std::to_string(steps.size()) +
                         " steps: a run of n scans has n poses and n − 1 steps");
  RunMapBuilder builder(settings);
  for (std::size_t k = 0; k < poses.size(); ++k) {
    PointCloud scan = load_sequence_scan(dataset, first + k, min_range);
    if (k < sweeps.size()) scan = deskew_scan(scan, sweeps[k]);  // as the chain registered it
    builder.add(RegisteredScan{k, &scan, poses[k], k == 0 ? nullptr : &steps[k - 1]});
  }
  return builder;
}

}  // namespace sextant
