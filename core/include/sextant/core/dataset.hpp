#pragma once
// A sequence of scans with optional odometry and ground truth, read through one interface
// whatever the source: a uos folder (hannover1 layout, and the built-in synthetic campus), a
// KITTI odometry sequence folder, or an in-memory dataset.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"

namespace sextant {

struct DatasetMetadata {
  std::string name;    ///< e.g. folder name
  std::string format;  ///< "uos", "kitti", "synthetic", ...
  std::filesystem::path path;
  std::size_t scan_count = 0;
  bool has_odometry = false;
  bool has_ground_truth = false;
};

/// What loading one scan cost: nothing is dropped without a count.
struct ScanLoadReport {
  std::size_t points_read = 0;
  std::size_t non_finite_dropped = 0;  ///< NaN/Inf coordinates
  std::size_t no_return_dropped = 0;   ///< scanner "no return" values (uos 3276 cm)
  std::size_t header_lines_skipped = 0;
};

class Dataset {
 public:
  virtual ~Dataset() = default;

  virtual const DatasetMetadata& metadata() const = 0;
  std::size_t size() const { return metadata().scan_count; }

  /// Scan i in the sensor frame (internal convention: metres, x forward, y left, z up).
  virtual PointCloud scan(std::size_t i, ScanLoadReport* report = nullptr) const = 0;
  /// World ← scan-i pose from odometry (dead reckoning), when the dataset has it.
  virtual std::optional<Eigen::Isometry3d> odometry(std::size_t i) const = 0;
  /// World ← scan-i true pose, when the dataset has it.
  virtual std::optional<Eigen::Isometry3d> ground_truth(std::size_t i) const = 0;
  /// Time of scan i [s], when the dataset has a clock (KITTI times.txt).
  virtual std::optional<double> stamp(std::size_t /*i*/) const { return std::nullopt; }
  /// The file scan i is read from (empty for in-memory datasets).
  virtual std::filesystem::path scan_file(std::size_t /*i*/) const { return {}; }
};

/// Opens a folder, detecting its layout (uos: scan000.3d…; KITTI: velodyne/ + poses/calib).
/// Throws InputError when the folder is neither.
/// Pose files are read when the folder is opened, so their errors surface at once.
std::unique_ptr<Dataset> open_dataset(const std::filesystem::path& folder);

/// A uos folder: scanNNN.3d sorted by number; odometry from every scanNNN.pose, ground truth
/// from the last line of every scanNNN.frames. Pose files present for some scans but missing for
/// others are an InputError naming the missing file.
std::unique_ptr<Dataset> open_uos_dataset(const std::filesystem::path& folder);
/// A KITTI odometry sequence folder: velodyne/NNNNNN.bin (or .xyz32.bin), calib.txt (Tr line),
/// optional poses.txt (else ../../poses/<folder name>.txt, the benchmark's layout) and times.txt.
/// Ground truth is the Velodyne-frame pose Tr⁻¹·P0⁻¹·Pi·Tr; KITTI has no odometry.
std::unique_ptr<Dataset> open_kitti_dataset(const std::filesystem::path& folder);

}  // namespace sextant
