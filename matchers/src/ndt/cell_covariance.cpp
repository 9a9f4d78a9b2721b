// A cell's information matrix (the covariance inflation after eq. 3.11), four cells per vector: the
// direct route for every cell, then the cells it cannot take gathered through the eigenvalues, where
// which of them are raised is a select per lane. Every lane takes the same IEEE operations, so a cell
// alone (in lane 0 of the same code) gets the bits it gets in a batch. The lanes
// (cell_covariance_lanes.inc) are compiled twice on x86-64, for plain x86-64 and with AVX2, like the
// split's (cell_split.cpp); this file is compiled with -ffp-contract=off (matchers/CMakeLists.txt), so
// both give the same bits (CellCovariance.* checks it).
#include "ndt/cell_covariance.hpp"

#include <algorithm>
#include <cstdint>

#include "ndt/cell_covariance_lanes.hpp"

#if SEXTANT_HAVE_AVX2
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#else
#include <cmath>
#endif

namespace sextant {

namespace {

using vd = double __attribute__((vector_size(4 * sizeof(double))));
using vm = std::int64_t __attribute__((vector_size(4 * sizeof(std::int64_t))));  // lane masks

namespace baseline {
#define SEXTANT_LANES_TARGET
inline vd sqrt_lanes(vd v) {
#if defined(__SSE2__)
  const __m128d lo = _mm_sqrt_pd(__m128d{v[0], v[1]}), hi = _mm_sqrt_pd(__m128d{v[2], v[3]});
  return vd{lo[0], lo[1], hi[0], hi[1]};
#else
  return vd{std::sqrt(v[0]), std::sqrt(v[1]), std::sqrt(v[2]), std::sqrt(v[3])};
#endif
}
#include "ndt/cell_covariance_lanes.inc"
#undef SEXTANT_LANES_TARGET
}  // namespace baseline

#if SEXTANT_HAVE_AVX2
namespace avx2 {
#define SEXTANT_LANES_TARGET __attribute__((target("avx2")))
SEXTANT_LANES_TARGET inline vd sqrt_lanes(vd v) {
  return reinterpret_cast<vd>(_mm256_sqrt_pd(reinterpret_cast<__m256d>(v)));
}
#include "ndt/cell_covariance_lanes.inc"
#undef SEXTANT_LANES_TARGET
}  // namespace avx2
#endif

/// C's upper triangle, xx xy xz yy yz zz.
void upper_of(const Eigen::Matrix3d& C, double upper[6]) {
  const double u[6] = {C(0, 0), C(0, 1), C(0, 2), C(1, 1), C(1, 2), C(2, 2)};
  std::copy(u, u + 6, upper);
}

}  // namespace

namespace ndt_detail {

void cells_information(const double* covariances, std::size_t n, double ratio, double least_spread,
                       double* information, bool* kept, InstructionSet isa) {
#if SEXTANT_HAVE_AVX2
  if (runs_avx2(isa)) return avx2::information_batch(covariances, n, ratio, least_spread, information, kept);
#endif
  (void)isa;
  baseline::information_batch(covariances, n, ratio, least_spread, information, kept);
}

}  // namespace ndt_detail

Eigen::Vector3d symmetric_eigenvalues(const Eigen::Matrix3d& C) {
  double upper[6];
  upper_of(C, upper);
  Eigen::Vector3d values;
#if SEXTANT_HAVE_AVX2
  if (runs_avx2(best_instruction_set())) {
    avx2::eigenvalues_one(upper, values.data());
    return values;
  }
#endif
  baseline::eigenvalues_one(upper, values.data());
  return values;
}

bool cell_information(const Eigen::Matrix3d& C, double ratio, double least_spread,
                      Eigen::Matrix3d& information) {
  double upper[6], inv[6];
  upper_of(C, upper);
  bool kept = false;
  ndt_detail::cells_information(upper, 1, ratio, least_spread, inv, &kept);
  if (!kept) return false;
  information << inv[0], inv[1], inv[2], inv[1], inv[3], inv[4], inv[2], inv[4], inv[5];
  return true;
}

}  // namespace sextant
