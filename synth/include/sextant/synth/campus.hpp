#pragma once
// The built-in synthetic campus (docs/design.md, "The synthetic campus"; docs/synthetic_campus.md):
// world, 6D ground truth, 2D odometry, GNSS, and scans generated on demand per index — scan(i)
// draws from its own Rng derived from (seed, i), so generating the scans in any order or on any
// number of threads gives identical bytes.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/dataset.hpp"
#include "sextant/synth/gnss.hpp"
#include "sextant/synth/sensor.hpp"
#include "sextant/synth/settings.hpp"
#include "sextant/synth/world.hpp"

namespace sextant::synth {

class Campus {
 public:
  CampusSettings settings;
  std::uint64_t seed = 0;
  std::shared_ptr<const World> world;
  std::vector<Eigen::Isometry3d> ground_truth;  ///< world ← sensor, 6D
  std::vector<Eigen::Isometry3d> odometry;      ///< world ← sensor, dead-reckoned 2D (z = roll = pitch = 0)
  std::vector<double> stamps;                   ///< [s]
  std::vector<GnssRecord> gnss;
  /// The route index of scan 0 (campus_window): a scan keeps the sensor noise it has in the whole
  /// campus.
  std::size_t first_scan = 0;
  /// World ← sensor one scan period after the last scan: the route's next pose, or past the route's end
  /// its last step continued (a sweeping sensor moves towards it during the last scan).
  Eigen::Isometry3d pose_after_last = Eigen::Isometry3d::Identity();

  std::size_t size() const { return ground_truth.size(); }
  /// Scan i (sensor frame) with per-point provenance. Throws std::out_of_range past the end. With
  /// sensor.sweep_period, the sensor sweeps while it moves from scan i's pose (the scan's ground truth,
  /// at its stamp: the sweep's start) towards scan i + 1's, at a constant velocity over the scan period
  /// (interpolate_motion), and every point carries its time.
  SimulatedScan scan(std::size_t i) const;
};

/// Generates everything except the scans (those come from Campus::scan). Throws
/// std::invalid_argument when the settings are not valid.
Campus generate_campus(const CampusSettings& settings, std::uint64_t seed);

/// Scans first … first + count − 1 of `campus` as a campus of their own (trajectory, odometry, stamps
/// and GNSS sliced, the same world; scan i is the whole campus' scan first + i, noise included).
/// Throws std::out_of_range when the window leaves the campus.
Campus campus_window(const Campus& campus, std::size_t first, std::size_t count);

/// All scans, in parallel (TBB); identical for any thread count.
std::vector<SimulatedScan> generate_all_scans(const Campus& campus);

/// The campus through core's Dataset interface, in memory (scans generated on demand).
class CampusDataset : public Dataset {
 public:
  explicit CampusDataset(Campus campus);

  const DatasetMetadata& metadata() const override { return metadata_; }
  PointCloud scan(std::size_t i, ScanLoadReport* report = nullptr) const override;
  std::optional<Eigen::Isometry3d> odometry(std::size_t i) const override;
  std::optional<Eigen::Isometry3d> ground_truth(std::size_t i) const override;

  const Campus& campus() const { return campus_; }

 private:
  Campus campus_;
  DatasetMetadata metadata_;
};

}  // namespace sextant::synth
