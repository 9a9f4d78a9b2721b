// The splitting process's two passes (cell_split.hpp). Their body (cell_split_lanes.inc) is compiled
// twice on x86-64, for plain x86-64 and with AVX2, like the score kernel's (mahalanobis_kernel.cpp);
// both give the same bits (CellSplit.* checks it). This file is compiled with -ffp-contract=off
// (matchers/CMakeLists.txt): no multiply-add is fused on one path and not on the other.
#include "ndt/cell_split.hpp"

#include <algorithm>
#include <cstring>

#if SEXTANT_HAVE_AVX2
#include <immintrin.h>
#endif

namespace sextant::ndt_detail {

namespace {

using vd = double __attribute__((vector_size(4 * sizeof(double))));
using vl = std::int64_t __attribute__((vector_size(4 * sizeof(std::int64_t))));
using vf = float __attribute__((vector_size(4 * sizeof(float))));
using vi4 = std::int32_t __attribute__((vector_size(4 * sizeof(std::int32_t))));

/// How far past the grid's far face a point still belongs to its last cell, in cells: the box is
/// closed, and (p − origin) / edge of a point on the face may round just above the cell count.
constexpr double kFarFace = 1e-9;

/// Pass 1 for one point.
inline std::uint32_t cell_of(const Eigen::Vector3f& p, const SplitGrid& g, double fx_max, double fy_max,
                             double fz_max) {
  const double fx = (static_cast<double>(p.x()) - g.ox) * g.inv_edge,
               fy = (static_cast<double>(p.y()) - g.oy) * g.inv_edge,
               fz = (static_cast<double>(p.z()) - g.oz) * g.inv_edge;
  if (!(fx >= 0.0 && fy >= 0.0 && fz >= 0.0 && fx <= fx_max && fy <= fy_max && fz <= fz_max)) return kOutside;
  const int x = std::min(static_cast<int>(fx), g.nx - 1), y = std::min(static_cast<int>(fy), g.ny - 1),
            z = std::min(static_cast<int>(fz), g.nz - 1);
  return static_cast<std::uint32_t>((z * g.ny + y) * g.nx + x);
}

namespace baseline {
#define SEXTANT_LANES_TARGET
inline vd widen(vf v) {
  return __builtin_convertvector(v, vd);
}
#include "ndt/cell_split_lanes.inc"
#undef SEXTANT_LANES_TARGET
}  // namespace baseline

#if SEXTANT_HAVE_AVX2
namespace avx2 {
#define SEXTANT_LANES_TARGET __attribute__((target("avx2")))
// Four floats to four doubles in one instruction (GCC 12 converts the vector in halves).
SEXTANT_LANES_TARGET inline vd widen(vf v) {
  return reinterpret_cast<vd>(_mm256_cvtps_pd(reinterpret_cast<__m128>(v)));
}
#include "ndt/cell_split_lanes.inc"
#undef SEXTANT_LANES_TARGET
}  // namespace avx2
#endif

}  // namespace

void assign_cells(PointsView points, const SplitGrid& grid, std::uint32_t* cells, InstructionSet isa) {
#if SEXTANT_HAVE_AVX2
  if (runs_avx2(isa)) return avx2::assign(points.data(), points.size(), grid, cells);
#endif
  (void)isa;
  baseline::assign(points.data(), points.size(), grid, cells);
}

std::vector<CellSums> accumulate_cells(PointsView points, const std::uint32_t* cells, const SplitGrid& grid,
                                       std::int32_t* index, InstructionSet isa) {
#if SEXTANT_HAVE_AVX2
  if (runs_avx2(isa)) return avx2::accumulate(points.data(), points.size(), cells, grid, index);
#endif
  (void)isa;
  return baseline::accumulate(points.data(), points.size(), cells, grid, index);
}

}  // namespace sextant::ndt_detail
