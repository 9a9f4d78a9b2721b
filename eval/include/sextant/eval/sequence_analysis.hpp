#pragma once
// Analyses of per-step sequences of a SLAM run, for the verdicts of E17 and E19:
//   - how a per-step cost grows with the map: the least-squares slope of time against map size
//     with a percentile-bootstrap interval over the (size, time) pairs (E17: "SEIF flat, EKF
//     grows");
//   - spikes of a per-step error: robust z-scores (median, 1.4826·MAD) above a threshold, one per
//     neighbourhood (E19: "Kümmerle's relative errors spike at the loop closures");
//   - where a route revisits earlier places: the first scan of each run of scans whose true
//     position comes within a radius of a scan at least `min_gap` scans earlier.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/eval/verdict.hpp"

namespace sextant {

struct LineFit {
  double slope = 0.0;      ///< dy/dx
  double intercept = 0.0;  ///< y at x = 0
  std::size_t n = 0;       ///< finite (x, y) pairs used
  bool defined() const;    ///< at least 2 pairs and x not constant
};

/// Ordinary least squares y ≈ intercept + slope·x over the pairs where both are finite.
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

/// The slope of fit_line with a percentile-bootstrap interval: the finite (x, y) pairs are
/// resampled with replacement `resamples` times (resamples with constant x are skipped).
/// Undefined (NaN) when the fit is. Deterministic in `seed`.
Interval bootstrap_slope(const std::vector<double>& x, const std::vector<double>& y, std::uint64_t seed,
                         double confidence = 0.95, int resamples = 2000);

/// Indices i with (v_i − median) / (1.4826·MAD) > threshold that are the largest value within
/// ±separation (ties: the first). NaN values are ignored. When the MAD is 0, any value above the
/// median counts as infinitely far. Ascending.
std::vector<std::size_t> robust_spikes(const std::vector<double>& values, double threshold = 5.0,
                                       std::size_t separation = 5);

/// Scan k revisits when ‖p_k − p_j‖ < radius (x, y, z) for some j ≤ k − min_gap. Returns the first
/// scan of every maximal run of consecutive revisiting scans, ascending.
std::vector<std::size_t> revisit_starts(const std::vector<Eigen::Vector3d>& positions, double radius,
                                        std::size_t min_gap);

/// For each index, the distance (in steps) to the nearest of `events`; SIZE_MAX when there are none.
std::vector<std::size_t> distance_to_nearest(const std::vector<std::size_t>& indices,
                                             const std::vector<std::size_t>& events);

}  // namespace sextant
