#pragma once
// A sequence of scans with optional odometry and ground truth, read through one interface
// whatever the source: a uos folder (hannover1 layout, and the built-in synthetic campus), a
// KITTI odometry sequence folder, or an in-memory dataset.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

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
  /// What a user must hear about the folder: gaps in the scan numbering, mixed file formats (each
  /// reported, not an error; ambiguous numbering is an InputError when the folder is opened).
  std::vector<std::string> notes;
};

/// What loading one scan cost: nothing is dropped without a count.
struct ScanLoadReport {
  std::size_t points_read = 0;
  std::size_t non_finite_dropped = 0;  ///< NaN/Inf coordinates
  std::size_t no_return_dropped = 0;   ///< scanner "no return" values (uos 3276 cm)
  std::size_t header_lines_skipped = 0;
  /// What the reader doubts without refusing the file (`sextant info` prints them), e.g. a `.bin`
  /// whose fourth column does not look like intensity.
  std::vector<std::string> warnings;
  std::size_t dropped() const { return non_finite_dropped + no_return_dropped; }
};

/// "6499 of 12998 points dropped (6499 non-finite, 0 no-return)", or empty when none was.
std::string dropped_points_note(const ScanLoadReport& report);

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
  /// Time of scan i [s], when the dataset has a clock (times.txt, names that are times, a recording).
  virtual std::optional<double> stamp(std::size_t /*i*/) const { return std::nullopt; }
  /// The file scan i is read from (empty for in-memory datasets).
  virtual std::filesystem::path scan_file(std::size_t /*i*/) const { return {}; }
};

/// Opens a folder, detecting its layout: KITTI (a velodyne/ folder), uos (scanNNN.3d files), else a
/// scan folder (open_scan_folder). Throws InputError when the folder holds no scans.
/// Pose files are read when the folder is opened, so their errors surface at once.
std::unique_ptr<Dataset> open_dataset(const std::filesystem::path& folder);

/// The point-cloud extensions a scan folder is made of: .pcd .ply .bin .xyz32.bin .xyz .csv .3d.
const std::vector<std::string>& scan_folder_extensions();

/// Any folder of scans: the files of scan_folder_extensions() in `folder`, or in `folder/scans`
/// when `folder` holds none, in natural order (by the last number in the name: full2 before
/// full10; a number with a fraction by its value: 1565943695.9 before 1565943696.1; when every name
/// is such a number, as a bag export names them, those numbers are the scans' times). Optional, beside the
/// scans' folder or in `folder`: `poses.txt` (one 3×4 row-major world ← scan matrix per line, the KITTI
/// layout without calibration: the ground truth) and `times.txt` (one time [s] per scan). `poses_file`, when
/// given, replaces poses.txt: TUM (8 numbers per line) or KITTI (12 per line), one pose per scan, in order. A
/// pose or time count that differs from the scan count, two files with the same number, a scan that is a link
/// to nothing, and scans both in `folder` and in `folder/scans`, are InputErrors; gaps in the numbering,
/// mixed formats and cloud files left out (no number in the name) are notes in the metadata.
std::unique_ptr<Dataset> open_scan_folder(const std::filesystem::path& folder,
                                          const std::filesystem::path& poses_file = {});

/// A uos folder: scanNNN.3d sorted by number; odometry from every scanNNN.pose, ground truth
/// from the last line of every scanNNN.frames. Pose files present for some scans but missing for
/// others are an InputError naming the missing file.
std::unique_ptr<Dataset> open_uos_dataset(const std::filesystem::path& folder);
/// A KITTI odometry sequence folder: velodyne/NNNNNN.bin (or .xyz32.bin), calib.txt (Tr line),
/// optional poses.txt (else ../../poses/<folder name>.txt, the benchmark's layout) and times.txt.
/// Ground truth is the Velodyne-frame pose Tr⁻¹·P0⁻¹·Pi·Tr; KITTI has no odometry.
std::unique_ptr<Dataset> open_kitti_dataset(const std::filesystem::path& folder);

}  // namespace sextant
