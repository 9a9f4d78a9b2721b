#pragma once
// A wider basin for ML-NDT (issue 14; beyond §5's "up to 25 units and 15°, sometimes 45°"): a
// global initialisation stage before the layer pyramid. Pose hypotheses around the initial guess,
// yaw every `yaw_step_deg` over ±`yaw_range_deg` × a square grid of x/y offsets every
// `translation_step` over ±`translation_range`, are scored by the truncated Mahalanobis score
// (eq. 3.11, each term min(eᵀC⁻¹e, τ), τ charged for points without a Gaussian) of a fixed,
// evenly strided subsample of the input at one coarse layer: the finest layer whose cell edge is
// at least twice the translation step, so that the nearest hypothesis to the true pose (≤ half a
// step off in x and y, ≤ half a yaw step in rotation) still puts most points in their own cell or
// a neighbour (measured in bench_wide_basin: one translation step gave a too narrow score peak). The
// `candidates` best hypotheses that differ by more than one grid step, the `horizon_candidates` best
// by the input's points above the horizon alone (horizon_check.hpp: a lidar's ground rings rank the
// hypotheses about no translation best), and the initial guess are refined by ML-NDT: the guess as an
// ordinary registration, each hypothesis from the layer it was scored at (it is resolved to that layer's
// cells; the coarser ones pulled real keyframes back to zero motion). The run chosen is
// MlndtMatcher::align's: one that passes the trust checks, else the lowest final score; the others are the
// result's alternatives (registration_quality.hpp).
//
// A guess off in roll or pitch is outside that grid. A view all around brings its own tilt back, a
// narrow one does not (docs/matcher_defaults.md, "Tilted starts"). So when no run from the guess or a level
// hypothesis passes the trust checks and the input covers less than kSpinningCoverage of the azimuth circle
// (sensor_kind.hpp), tilted hypotheses are scored too, every yaw × roll × pitch every `tilt_step_deg`
// over ±`tilt_range_deg` about the input's own axes at the guess' position, and the best
// `tilt_candidates` refined; only then, as each start that ends elsewhere is one more rival of a right
// answer.
//
// The settings: sextant/matchers/wide_basin_settings.hpp.
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "ndt/ndt_score.hpp"
#include "sextant/core/point_cloud.hpp"
#include "sextant/matchers/ndt_grid.hpp"
#include "sextant/matchers/wide_basin_settings.hpp"

namespace sextant {

/// The scoring layer: index of the finest of `layers` whose cell edge is ≥ `min_edge` (0, layer
/// 1, when none is); wide_basin_starts() asks for 2 × translation_step.
std::size_t wide_basin_layer(const std::vector<NdtGrid>& layers, double min_edge);

/// Starting poses for the refinement, best first: the initial guess, then up to `candidates`
/// mutually distinct hypotheses in order of score. The hypotheses are scored side by side on
/// `threads` (the same starts for any thread count).
std::vector<Eigen::Isometry3d> wide_basin_starts(const std::vector<NdtGrid>& layers, const PointCloud& input,
                                                 const Eigen::Isometry3d& initial,
                                                 const WideBasinSettings& settings,
                                                 const ScoreThreads& threads = ScoreThreads());

/// The best `tilt_candidates` mutually distinct tilted hypotheses (yaw × roll × pitch about the input's
/// axes, at the guess' position, none level), best first, scored as wide_basin_starts scores.
std::vector<Eigen::Isometry3d> wide_basin_tilted_starts(const std::vector<NdtGrid>& layers,
                                                        const PointCloud& input,
                                                        const Eigen::Isometry3d& initial,
                                                        const WideBasinSettings& settings,
                                                        const ScoreThreads& threads = ScoreThreads());

}  // namespace sextant
