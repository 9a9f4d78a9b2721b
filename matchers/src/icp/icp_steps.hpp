#pragma once
// One ICP increment from a fixed set of correspondences, the part of an ICP iteration that is
// pure linear algebra (separate from the search so it can be tested on exact data).
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/pose.hpp"
#include "sextant/matchers/dof_mask.hpp"

namespace sextant {

/// Matched pairs, input point p (already mapped by the current estimate) ↔ reference point q,
/// with the reference normal n for point-to-plane (unused and may be empty for point-to-point).
struct Correspondences {
  std::vector<Eigen::Vector3d> input;
  std::vector<Eigen::Vector3d> reference;
  std::vector<Eigen::Vector3d> normals;

  std::size_t size() const { return input.size(); }
  void clear() {
    input.clear();
    reference.clear();
    normals.clear();
  }
};

/// The increment ΔT with p_ref ≈ ΔT·p, its parameters and the Gauss–Newton information.
struct IcpStep {
  bool ok = false;
  std::string problem;  ///< why not ok (degenerate geometry, …)
  Eigen::Isometry3d delta = Eigen::Isometry3d::Identity();
  Vector6d xi = Vector6d::Zero();  ///< [Δt Δα Δβ Δγ] of delta, eq. (3.8)
  Matrix6d H = Matrix6d::Zero();   ///< JᵀJ of the residuals w.r.t. a left increment at the pairs
  double score_before = 0.0;       ///< mean squared residual before the step [m²]
  double score_after = 0.0;        ///< mean squared residual after the step, same pairs [m²]
};

/// Least squares Σ‖ΔT·p − q‖². With all six parameters free: closed form (Arun/Horn: SVD of
/// the cross-covariance, with the reflection fixed), failing when the pairs are fewer than 3 or
/// collinear. With a DOF mask: one linearised Gauss–Newton step over the free parameters only
/// (J = [I, −[p]×]), failing when that reduced system is singular.
IcpStep point_to_point_step(const Correspondences& pairs, const DofMask& dof = {});

/// Linearised least squares Σ (nᵀ(ΔT·p − q))² with ΔT ≈ [I + [ω]×, Δt], one solve over the
/// free parameters of `dof`; fails when that system is singular (e.g. all normals parallel).
IcpStep point_to_plane_step(const Correspondences& pairs, const DofMask& dof = {});

}  // namespace sextant
