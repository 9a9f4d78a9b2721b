#pragma once
// How the sequential chain deskews its scans (private to Sextant::odometry; deskew.hpp; the scheme and
// its measurements: docs/odometry.md, "Scans taken while moving"). Each scan whose points carry time is
// deskewed into its frame at its stamp by the velocity around it:
//   - with the odometry guess, the odometry's motion from the scan before (scan 0: to scan 1);
//   - else the velocity the chain measured at its last believed step, taken between the middles of the
//     two scans' sweeps, not between their stamps: a registration places a scan best where its points
//     are on average, the middle of its sweep, while a velocity error δ moves the frame at the stamp by
//     about δ · sweep / 2, an error a velocity taken between stamps would feed into the next deskew;
//   - scans taken before any velocity was known are deskewed once the first is;
//   - after a step, the velocity the step itself measured is the best there is of the motion around its
//     scan (its sweep overlaps the step): when it would move some point by more than
//     kRegisterAgainMetres from where the first deskew put it, the scan is deskewed by it and the step
//     registered again.
#include <cstddef>
#include <deque>
#include <optional>

#include <Eigen/Geometry>

#include "sextant/core/dataset.hpp"
#include "sextant/odometry/deskew.hpp"
#include "sextant/odometry/odometry.hpp"

namespace sextant::odometry_detail {

/// How far a second deskew must move some point before the step is registered again [m]: the size of a
/// registration's own error on a good scan (a few cm) is not worth a second registration.
inline constexpr double kRegisterAgainMetres = 0.1;

/// The frame at the middle of a scan's sweep ((earliest + latest time) / 2) in its frame at the stamp,
/// under `sweep`; the identity for a scan without time or a sweep without a known motion.
Eigen::Isometry3d mid_sweep_pose(const PointCloud& scan, const SweepMotion& sweep);

class ChainDeskew {
 public:
  /// Deskews when `enabled`, recording each scan's sweep in result.sweeps (sized by run_odometry) and
  /// counting result.timed_scans; scan k of the run is scan first + k of `dataset`.
  ChainDeskew(const Dataset& dataset, std::size_t first, bool enabled, OdometryResult& result);

  /// Scan k as the chain registers it and keeps it in the map: deskewed by `odometry_motion` when given,
  /// else by the velocity measured so far (none yet: as read). Its points as read are kept while it is
  /// in the map.
  PointCloud take(std::size_t k, PointCloud scan, const std::optional<Eigen::Isometry3d>& odometry_motion);

  /// After step k's first registration, `relative`: scan k deskewed by the velocity the step measured,
  /// when that moves some point by more than kRegisterAgainMetres (register the step again with it);
  /// nothing otherwise. Scan k's sweep is then the step's, until keep_first. The map's scans no velocity
  /// has deskewed yet (`window`, scan k − 1 last) are deskewed by it too; `map_changed` says whether any was.
  std::optional<PointCloud> deskewed_again(std::size_t k, const Eigen::Isometry3d& relative,
                                           std::deque<PointCloud>& window, bool& map_changed);
  /// The second registration is not kept: scan k's sweep is the first again.
  void keep_first(std::size_t k);

  /// Step k (scan k − 1 → k) was chained with `relative` and believed: its velocity is the one the next
  /// scans are deskewed by, and the map's scans no velocity has deskewed yet are deskewed by it. `window`
  /// holds the map's scans as taken, scan k last.
  void learn(std::size_t k, const Eigen::Isometry3d& relative, std::deque<PointCloud>& window);

  /// The map keeps its last `n` scans: so are their points as read.
  void keep_last(std::size_t n);

 private:
  /// The velocity step k measured with `relative`, between the sweeps' middles; unknown without times.
  SweepMotion step_velocity(std::size_t k, const Eigen::Isometry3d& relative) const;
  /// Deskews by `velocity` the scans of `window` (its last is scan `newest`) that carry time and no
  /// velocity has deskewed yet; whether any was.
  bool deskew_the_rest(std::deque<PointCloud>& window, std::size_t newest, const SweepMotion& velocity);

  const Dataset& dataset_;
  std::size_t first_;
  bool enabled_;
  OdometryResult& result_;
  std::deque<PointCloud> raw_;  ///< the map's scans as read, oldest first, then the scan being registered
  SweepMotion velocity_;        ///< measured at the last believed step; unknown before the first
  SweepMotion first_sweep_;     ///< scan k's sweep before deskewed_again
};

}  // namespace sextant::odometry_detail
