#pragma once
// The map of an odometry run (run_map.hpp) as both faces build it: during the run, from each scan
// run_odometry hands its observer, or after it, from the final poses when they changed (loop closure),
// re-reading the scans one at a time.
//
//   RunMapBuilder builder(RunMapSettings{});              // default voxel, every scan
//   run_odometry(dataset, s, first, count, progress, builder.observer());
//   write_cloud("map.ply", builder.map().cloud());
//
// Every scan goes in by default, those placed by an untrusted step too: the map is the trajectory's,
// and a wrong step shows in it where it happened (a doubled wall, a smeared street), as it does in the
// trajectory. trusted_only leaves those scans out, for a cleaner map of a run whose untrusted steps
// are known to be wrong; the scans after them stay, placed by the chain that went through them.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/dataset.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/pipeline/run_map.hpp"

namespace sextant {

struct RunMapSettings {
  std::optional<double> voxel;  ///< [m]; none: default_map_voxel_size of the run's first scan
  bool trusted_only = false;    ///< leave out the scans placed by an untrusted step
};

/// How a run's map came out (printed, and recorded in provenance.json).
struct RunMapSummary {
  double voxel = 0.0;              ///< [m]
  bool default_voxel = true;       ///< chosen from the first scan (else given)
  double median_range = 0.0;       ///< the first scan's median range, the default voxel's scale [m]
  std::size_t points = 0;          ///< the map's points (occupied voxels)
  std::size_t scans = 0;           ///< scans in the map
  std::size_t scans_left_out = 0;  ///< placed by an untrusted step (trusted_only)
  std::size_t skipped_points = 0;  ///< outside the voxel index's range (RunMap::skipped_points)
  bool intensity = false;          ///< the map keeps intensity (every scan had it)
  /// "1/100 of the first scan's median range, 14.3 m" or "given"
  std::string voxel_origin() const;
};

class RunMapBuilder {
 public:
  /// InputError for a given voxel that is not finite and > 0.
  explicit RunMapBuilder(RunMapSettings settings);
  RunMapBuilder(RunMapBuilder&&) = default;
  RunMapBuilder& operator=(RunMapBuilder&&) = default;

  /// Adds the scan (or, with trusted_only, counts it left out when its step is not trusted). The
  /// first scan added sets the default voxel.
  void add(const RegisteredScan& scan);
  /// add() as run_odometry's observer; it refers to this builder, which must outlive the run.
  OdometryScanObserver observer();

  /// The map; std::logic_error before the first scan.
  const RunMap& map() const;
  RunMapSummary summary() const;

 private:
  RunMapSettings settings_;
  std::optional<RunMap> map_;
  bool seen_first_ = false;
  double median_range_ = 0.0;
  std::size_t left_out_ = 0;
};

/// The map of a finished run of scans first … first + poses.size() − 1 placed by `poses` (world ←
/// scan, e.g. the loop-closed ones), each scan re-read as the chain read it (load_sequence_scan with
/// `min_range`, deskewed by `sweeps`, the run's OdometryResult::sweeps, when given) and dropped once added.
/// `steps` are the chain's (poses.size() − 1 of them): with trusted_only, scan k ≥ 1 is left out when steps[k
/// − 1] is not trusted. InputError when the sizes disagree.
RunMapBuilder build_run_map(const Dataset& dataset, std::size_t first,
                            const std::vector<Eigen::Isometry3d>& poses,
                            const std::vector<OdometryStep>& steps, double min_range,
                            const RunMapSettings& settings, const std::vector<SweepMotion>& sweeps = {});

}  // namespace sextant
