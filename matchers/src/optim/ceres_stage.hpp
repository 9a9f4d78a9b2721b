#pragma once
// Ceres' Levenberg–Marquardt on one Mahalanobis stage: residuals Lᵀe per point (C⁻¹ = L·Lᵀ),
// so ½Σ‖Lᵀe‖² is half the score of eq. (3.11); a constant residual √penalty for points
// without a Gaussian and √τ for terms truncated at eᵀC⁻¹e > τ (both with zero Jacobian, as in
// the Newton and LM paths); one 6-parameter pose block.
#include <vector>

#include "sextant/matchers/dof_mask.hpp"
#include "sextant/matchers/ndt_grid.hpp"
#include "sextant/matchers/registration_result.hpp"

namespace sextant {

struct CeresStageOutcome {
  Vector6d xi = Vector6d::Zero();
  int iterations = 0;
  bool converged = false;  ///< Ceres reported convergence (parameter/function/gradient tolerance)
  bool failed = false;     ///< Ceres reported failure
  std::vector<IterationTrace> trace;
};

CeresStageOutcome solve_stage_with_ceres(const NdtGrid& grid, const PointCloud& input, const Vector6d& xi,
                                         int max_iterations, double epsilon, double unmatched_penalty,
                                         double max_distance, const DofMask& dof, int label,
                                         int iteration_offset);

}  // namespace sextant
