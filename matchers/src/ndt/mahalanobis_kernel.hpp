#pragma once
// Internal: the hot loop of the Mahalanobis (ML-NDT) score, eqs. (3.11), (3.13)–(3.15), over one
// block of input points (ndt_score.cpp sums the blocks in a fixed order).
#include <Eigen/Core>

#include "ndt/instruction_set.hpp"
#include "ndt/ndt_score.hpp"
#include "ndt/score_sums.hpp"
#include "sextant/matchers/ndt_grid.hpp"

namespace sextant::score_detail {

/// Adds the terms of the points [begin, end) mapped by u = R·x, x + t, to `s` (unweighted: the
/// factor 2 of eqs. 3.14–3.15 is applied by the caller). Points beyond `max_q` are counted in
/// `s.rejected` and add nothing. The matched points are processed four at a time, one per SIMD
/// lane, with each lane summed separately and the lanes added in order at the end of the block: a
/// fixed order for a given block, independent of the thread count and of `isa` (instruction_set.hpp;
/// an unavailable one falls back to the baseline).
void mahalanobis_block(const NdtGrid& grid, const Eigen::Vector3f* begin, const Eigen::Vector3f* end,
                       const Eigen::Matrix3d& R, const Eigen::Vector3d& t, double max_q,
                       Derivatives derivatives, Sums& s, InstructionSet isa = best_instruction_set());

}  // namespace sextant::score_detail
