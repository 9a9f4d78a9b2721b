// The Mahalanobis score kernel (mahalanobis_kernel.hpp). Its body (mahalanobis_lanes.inc) is
// compiled twice on x86-64: for plain x86-64 (SSE2) and with AVX2 for the CPUs that have it, chosen
// once at run time. Both give the same bits (KernelInstructionSet.* checks it): the body's lanes do
// the same IEEE operations in the same order, and this file is compiled with -ffp-contract=off
// (matchers/CMakeLists.txt), so no multiply-add is fused on one path and not on the other.
#include "ndt/mahalanobis_kernel.hpp"

#include <cstdint>

namespace sextant::score_detail {

namespace {

constexpr int kLanes = 4;
using vd = double __attribute__((vector_size(kLanes * sizeof(double))));
using vi = std::int64_t __attribute__((vector_size(kLanes * sizeof(std::int64_t))));

/// Matched points are staged (rotated point, Gaussian index) in chunks, then consumed kLanes at a time.
constexpr int kChunk = 256;

/// Per-lane running sums (upper triangles of P and S).
struct Lanes {
  vd score{}, gx{}, gy{}, gz{};
  vd n[9]{};
  vd p[6]{};
  vd q[9]{};
  vd s[6]{};
};

namespace baseline {
#define SEXTANT_LANES_TARGET
#include "ndt/mahalanobis_lanes.inc"
#include "ndt/ndt_score.hpp"
#undef SEXTANT_LANES_TARGET
}  // namespace baseline

#if SEXTANT_HAVE_AVX2
namespace avx2 {
#define SEXTANT_LANES_TARGET __attribute__((target("avx2")))
#include "ndt/mahalanobis_lanes.inc"
#undef SEXTANT_LANES_TARGET
}  // namespace avx2
#endif

template <bool kGradient, bool kHessian>
void block(InstructionSet isa, const NdtGrid& grid, const Eigen::Vector3f* begin, const Eigen::Vector3f* end,
           const Eigen::Matrix3d& R, const Eigen::Vector3d& t, double max_q, Sums& s) {
#if SEXTANT_HAVE_AVX2
  if (isa == InstructionSet::kAvx2) return avx2::block<kGradient, kHessian>(grid, begin, end, R, t, max_q, s);
#endif
  (void)isa;
  baseline::block<kGradient, kHessian>(grid, begin, end, R, t, max_q, s);
}

}  // namespace

void mahalanobis_block(const NdtGrid& grid, const Eigen::Vector3f* begin, const Eigen::Vector3f* end,
                       const Eigen::Matrix3d& R, const Eigen::Vector3d& t, double max_q,
                       Derivatives derivatives, Sums& s, InstructionSet isa) {
  if (grid.empty()) return;
  if (!instruction_set_available(isa)) isa = InstructionSet::kBaseline;
  switch (derivatives) {
    case Derivatives::kScore: block<false, false>(isa, grid, begin, end, R, t, max_q, s); break;
    case Derivatives::kGradient: block<true, false>(isa, grid, begin, end, R, t, max_q, s); break;
    case Derivatives::kHessian: block<true, true>(isa, grid, begin, end, R, t, max_q, s); break;
  }
}

}  // namespace sextant::score_detail
