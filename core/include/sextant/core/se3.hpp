#pragma once
// The exponential and logarithm of SE(3) in closed form, and the motion interpolated along them: the
// pose a body reaches at a constant velocity (a constant twist in its own frame) after a fraction of
// the time it took to make a motion T. Used to undo a sweeping lidar's motion (deskew) and to move
// the synthetic sensor along its sweep.
//
// A twist ξ = (ρ, φ): translation part ρ [m], rotation vector φ [rad] (θ = |φ|, Φ = [φ]×). The formulas
// (E. Eade, "Lie Groups for 2D and 3D Transformations", the SE(3) exponential map and its inverse,
// https://www.ethaneade.com/lie.pdf; Rodrigues' formula for R):
//   exp ξ = [R  V·ρ; 0 1],  R = I + (sin θ/θ)·Φ + ((1 − cos θ)/θ²)·Φ²,
//                            V = I + ((1 − cos θ)/θ²)·Φ + ((θ − sin θ)/θ³)·Φ²
//   log T: φ from R (angle and axis, θ ∈ [0, π]), ρ = V⁻¹·t,
//          V⁻¹ = I − ½·Φ + (1/θ²)·(1 − θ·sin θ / (2·(1 − cos θ)))·Φ²
// with the coefficients' Taylor series near θ = 0.
#include <Eigen/Geometry>

#include "sextant/core/pose.hpp"

namespace sextant {

/// exp of the twist ξ = (ρ, φ) (the formula above).
Eigen::Isometry3d se3_exp(const Vector6d& twist);
/// log of a rigid motion: the twist ξ = (ρ, φ) with exp ξ = T and |φ| ≤ π.
Vector6d se3_log(const Eigen::Isometry3d& T);

/// exp(s · log T): where a body that makes the motion T at a constant velocity (in its own frame) is
/// after the fraction s of the time (s = 0: identity, 1: T, 0.5 twice gives T; s < 0 or > 1
/// extrapolates). A screw motion: on a circular arc at constant speed it stays on the arc.
Eigen::Isometry3d interpolate_motion(const Eigen::Isometry3d& T, double s);

}  // namespace sextant
