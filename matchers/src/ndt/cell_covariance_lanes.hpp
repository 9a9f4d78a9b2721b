#pragma once
// Internal: cell_information (sextant/matchers/cell_covariance.hpp) for many cells at once, four per
// vector, as NdtGrid's generative process takes them. Compiled for every instruction set
// (instruction_set.hpp); a cell gives the same bits alone, in a batch and on each instruction set.
#include <cstddef>

#include "ndt/instruction_set.hpp"

namespace sextant::ndt_detail {

/// `covariances` holds the upper triangles (xx xy xz yy yz zz) of n symmetric matrices, `information`
/// receives theirs, and `kept[i]` says whether cell i was kept (where it was not, its six numbers are
/// unspecified).
void cells_information(const double* covariances, std::size_t n, double ratio, double least_spread,
                       double* information, bool* kept, InstructionSet isa = best_instruction_set());

}  // namespace sextant::ndt_detail
