#pragma once
// A real sequence with a reference but no odometry (MulRan: a lidar-inertial reference, no wheel
// odometry) given an odometry simulated from its reference with the campus' error model
// (synth::simulate_odometry: table 5.1's biased, heavy-tailed 2D model, or the zero-mean Gaussian
// one), so that the thesis' experiments that start from an odometry guess run on real
// scans. The odometry is a stated model, not a measurement; the metadata says so.
//
//   dataset: {source: folder, path: ../data/mulran_riverside02_excerpt, seed: 1,
//             simulated_odometry: {model: thesis}}     # any key of the campus' odometry: block
#include <cstdint>
#include <memory>
#include <vector>

#include "sextant/core/dataset.hpp"
#include "sextant/synth/settings.hpp"

namespace sextant {

class SimulatedOdometryDataset final : public Dataset {
 public:
  /// InputError (naming the folder) when `inner` lacks a reference pose for some scan.
  SimulatedOdometryDataset(std::unique_ptr<Dataset> inner, const synth::OdometrySettings& settings,
                           std::uint64_t seed);

  const DatasetMetadata& metadata() const override { return metadata_; }
  PointCloud scan(std::size_t i, ScanLoadReport* report = nullptr) const override {
    return inner_->scan(i, report);
  }
  std::optional<Eigen::Isometry3d> odometry(std::size_t i) const override;
  std::optional<Eigen::Isometry3d> ground_truth(std::size_t i) const override {
    return inner_->ground_truth(i);
  }
  std::optional<double> stamp(std::size_t i) const override { return inner_->stamp(i); }
  std::filesystem::path scan_file(std::size_t i) const override { return inner_->scan_file(i); }

 private:
  std::unique_ptr<Dataset> inner_;
  DatasetMetadata metadata_;
  std::vector<Eigen::Isometry3d> odometry_;
};

}  // namespace sextant
