#pragma once
// A nearly straight trajectory leaves the alignment's rotation about its direction free: Umeyama's
// fit (umeyama.hpp) of positions that lie close to one line is the same for any rotation about
// that line, so noise picks one (on MulRan Riverside 0–107, 129 m × 1.6 m × 0.5 m of spread, it
// turned the estimate 90–126° about the road and reported that as the ATE's rotation error).
//
// The rotation about the line is observable from the positions when their spread across the line
// exceeds what the alignment leaves unexplained. When the second principal spread σ₂ of the
// reference positions is below 3 × the RMS position residual, the roll about the principal axis a
// is taken from the orientations instead: the circular mean, over the poses, of the twist about a
// of R_ref,i · (R · R_est,i)ᵀ (swing–twist decomposition). A rotation about a moves points on the
// line through the centroid along no direction, so the position fit is unchanged.
#include "sextant/eval/trajectory_metrics.hpp"
#include "sextant/eval/umeyama.hpp"

namespace sextant {

/// `alignment` (positions of `estimate` onto `reference`) with the rotation about the reference's
/// principal direction resolved from the orientations when the positions leave it free; `resolved`
/// says whether they did.
Similarity3 resolve_roll_about_trajectory(const Similarity3& alignment, const PoseList& estimate,
                                          const PoseList& reference, bool* resolved = nullptr);

}  // namespace sextant
