#pragma once
// A nearly straight trajectory leaves the alignment's rotation about its direction free: Umeyama's
// fit (umeyama.hpp) of positions that lie close to one line barely changes with a rotation about
// that line, so the positions' errors pick one: on a nearly straight road it can turn a right
// estimate by tens of degrees or more about the road (docs/odometry.md, "What it prints and writes").
//
// A roll θ about the principal axis a of the reference positions moves them by θ·d (RMS), d the RMS
// distance of the positions from a; the fit cannot tell apart rolls whose displacement stays within
// the RMS position residual r, so the positions fix the roll to about r / d. When that exceeds
// kRollTolerance, and the orientations fix it better (their twists about a scatter less than r / d),
// the roll about a is taken from the orientations instead: the circular mean, over the poses, of
// the twist about a of R_ref,i · (R · R_est,i)ᵀ (swing–twist decomposition). A rotation about a
// moves points on the line through the centroid along no direction, so the position fit is
// unchanged. Where the positions fix the roll to within kRollTolerance, the alignment is Umeyama's,
// as in every other tool.
#include "sextant/core/units.hpp"
#include "sextant/eval/trajectory_metrics.hpp"
#include "sextant/eval/umeyama.hpp"

namespace sextant {

/// The roll about the trajectory the positions may leave free before the orientations are asked
/// [rad]: 1°, above the rotation errors an ATE usually reports (0.1–1°).
inline constexpr double kRollTolerance = 1.0 * kRadPerDeg;

/// `alignment` (positions of `estimate` onto `reference`) with the rotation about the reference's
/// principal direction resolved from the orientations when the positions leave it free; `resolved`
/// says whether they did.
Similarity3 resolve_roll_about_trajectory(const Similarity3& alignment, const PoseList& estimate,
                                          const PoseList& reference, bool* resolved = nullptr);

}  // namespace sextant
