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
// YAML (key `wide_basin:` of mlndt and fbmlndt; absent = off, the thesis' registration):
//   wide_basin: {yaw_step_deg: 10, yaw_range_deg: 180, translation_step: 2,
//                translation_range: 16, sample_points: 512, prescreen_points: 128,
//                prescreen_keep: 512, candidates: 4, horizon_candidates: 4, max_distance: 16,
//                tilt_step_deg: 10, tilt_range_deg: 20, tilt_candidates: 2}
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/matchers/ndt_grid.hpp"
#include "sextant/matchers/ndt_score.hpp"

namespace sextant {

struct WideBasinSettings {
  bool enabled = false;             ///< set by the presence of the `wide_basin` key
  double yaw_step_deg = 10.0;       ///< spacing of the yaw hypotheses [°, > 0]
  double yaw_range_deg = 180.0;     ///< hypotheses over ±range around the guess [°, 0..180]
  double translation_step = 2.0;    ///< spacing of the x/y offset grid [m, > 0]
  double translation_range = 16.0;  ///< offsets over ±range in x and y around the guess [m, ≥ 0]
  /// Spacing of the tilt hypotheses about the input's own x and y axes (roll, pitch) [°, (0, 90]]
  double tilt_step_deg = 10.0;
  /// Tilts over ±range about x and y, each with every yaw, at the guess' position: a sensor that is not
  /// level, or turns fast about every axis (a hand-held one), moves little meanwhile [°, 0..90]
  double tilt_range_deg = 20.0;
  /// The best tilted hypotheses, refined only for a narrow view when no run from the guess or the level
  /// hypotheses passes the trust checks (see above). 0: no tilts [count, ≥ 0]
  int tilt_candidates = 2;
  int sample_points = 512;  ///< input points scored per hypothesis (evenly strided) [count]
  /// Every hypothesis is first scored with this many points (a strided subset of the sample),
  /// the best `prescreen_keep` are rescored with all `sample_points`; 0 scores all with all [count]
  int prescreen_points = 128;
  int prescreen_keep = 512;  ///< hypotheses rescored after the prescreen [count, ≥ candidates]
  int candidates = 4;        ///< best hypotheses refined by the full registration [count]
  /// Further hypotheses refined, the best by the input's points above the horizon alone (z > 0 in the
  /// input's frame, where a level spinning lidar's ground rings are not), distinct from the others;
  /// none when fewer than `prescreen_points` (without a prescreen `sample_points`) of the input lie
  /// there [count, ≥ 0]
  int horizon_candidates = 4;
  double max_distance = 16.0;  ///< τ of the hypothesis score [Mahalanobis units]
  bool valid(std::string* why) const;
  /// Level hypotheses (yaw × x/y) scored per registration.
  long hypotheses() const;
  /// Tilted hypotheses (yaw × roll × pitch, the level ones left out) scored when they are needed.
  long tilted_hypotheses() const;
};

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
