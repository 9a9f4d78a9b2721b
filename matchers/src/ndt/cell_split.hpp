#pragma once
// Internal: the splitting process of Table 3.1 (ndt_grid.cpp's NdtGrid::split), the running sums of
// eqs. (3.2)–(3.3) over every occupied cell of a dense grid, in two passes over the points. Each pass
// is compiled for every instruction set (instruction_set.hpp) and gives the same bits on each.
#include <cstdint>
#include <vector>

#include "ndt/instruction_set.hpp"
#include "sextant/core/point_cloud.hpp"

namespace sextant::ndt_detail {

/// Running sums of one occupied cell, relative to the grid origin (double precision): Σp and
/// the upper triangle of Σppᵀ (xx xy xz yy yz zz; p(i)·p(j) = p(j)·p(i) exactly, so the lower
/// triangle is the same numbers), with the cell's index along each axis.
struct CellSums {
  std::int32_t cell = 0;
  std::int32_t count = 0;
  std::int32_t x = 0, y = 0, z = 0;
  double sum[3] = {0.0, 0.0, 0.0};
  double sum_sq[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
};

/// The grid a split sorts points into: cubic cells of edge 1 / inv_edge from the origin, nx × ny × nz
/// of them, cell (x, y, z) at index (z·ny + y)·nx + x (below 2³¹: NdtGrid::init).
struct SplitGrid {
  double ox = 0.0, oy = 0.0, oz = 0.0, inv_edge = 0.0;
  int nx = 0, ny = 0, nz = 0;
};

/// A point outside the grid, or not finite.
constexpr std::uint32_t kOutside = 0xffffffffu;

/// Pass 1: every point's cell index, or kOutside. The grid is closed: a point on its far face
/// belongs to the last cell.
void assign_cells(PointsView points, const SplitGrid& grid, std::uint32_t* cells,
                  InstructionSet isa = best_instruction_set());

/// Pass 2: the sums of every occupied cell, in order of each cell's first point, adding the points of
/// a cell in their order. `index` (one entry per cell, all −1 on entry) receives each occupied cell's
/// position in the result.
std::vector<CellSums> accumulate_cells(PointsView points, const std::uint32_t* cells, const SplitGrid& grid,
                                       std::int32_t* index, InstructionSet isa = best_instruction_set());

}  // namespace sextant::ndt_detail
