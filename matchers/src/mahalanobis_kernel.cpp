// The Mahalanobis score kernel, two matched points at a time (one per lane of a 2 × double vector:
// SSE2 on x86-64, NEON on arm64, plain scalar code elsewhere, via the GCC/Clang vector extension).
// Per point (rotated point u = R·x, cell mean μ, C⁻¹ = [[a b c] [b d e] [c e f]]):
//   e = u + t − μ (eq. 3.10), q = eᵀC⁻¹e (eq. 3.13), and the sums of ndt_score.cpp's header comment.
// A point beyond max_q (or the padding lane of an odd count) has its C⁻¹, C⁻¹e and q masked to
// zero, so it adds exact zeros.
#include "mahalanobis_kernel.hpp"

#include <cstdint>
#include <cstring>

namespace sextant::score_detail {

namespace {

using v2d = double __attribute__((vector_size(16)));
using v2i = std::int64_t __attribute__((vector_size(16)));

/// Matched points are staged (rotated point, Gaussian index) in chunks, then consumed in pairs.
constexpr int kChunk = 256;

/// Per-lane running sums (upper triangles of P and S).
struct Lanes {
  v2d score{}, gx{}, gy{}, gz{};
  v2d n[9]{};
  v2d p[6]{};
  v2d q[9]{};
  v2d s[6]{};
};

inline v2d pair(double x0, double x1) {
  return v2d{x0, x1};
}

inline v2d masked(v2d x, v2i keep) {
  return reinterpret_cast<v2d>(reinterpret_cast<v2i>(x) & keep);
}

inline double lane_sum(v2d x) {
  return x[0] + x[1];
}

template <bool kGradient, bool kHessian>
void pair_terms(const NdtGrid& grid, const double* ux, const double* uy, const double* uz, const int* g,
                v2d tx, v2d ty, v2d tz, v2d max_q, Lanes& l, Sums& s) {
  const CellGaussian& c0 = grid.gaussian(g[0] < 0 ? 0 : g[0]);
  const CellGaussian& c1 = grid.gaussian(g[1] < 0 ? 0 : g[1]);
  const v2d x = pair(ux[0], ux[1]), y = pair(uy[0], uy[1]), z = pair(uz[0], uz[1]);
  v2d a = pair(c0.inv_cov[0], c1.inv_cov[0]), b = pair(c0.inv_cov[1], c1.inv_cov[1]);
  v2d c = pair(c0.inv_cov[2], c1.inv_cov[2]), d = pair(c0.inv_cov[3], c1.inv_cov[3]);
  v2d e = pair(c0.inv_cov[4], c1.inv_cov[4]), f = pair(c0.inv_cov[5], c1.inv_cov[5]);
  const v2d ex = x + tx - pair(c0.mean[0], c1.mean[0]);  // eq. (3.10)
  const v2d ey = y + ty - pair(c0.mean[1], c1.mean[1]);
  const v2d ez = z + tz - pair(c0.mean[2], c1.mean[2]);
  v2d cx = a * ex + b * ey + c * ez;  // C⁻¹e
  v2d cy = b * ex + d * ey + e * ez;
  v2d cz = c * ex + e * ey + f * ez;
  v2d q = ex * cx + ey * cy + ez * cz;  // eᵀC⁻¹e, eq. (3.13)
  // Kept: a real point (not the padding) within the limit; !(q > max_q) keeps a NaN as the
  // scalar kernel does.
  const v2i real{g[0] >= 0 ? -1 : 0, g[1] >= 0 ? -1 : 0};
  const v2i beyond = reinterpret_cast<v2i>(q > max_q);
  const v2i keep = real & ~beyond;
  const v2i rejected = real & beyond;
  s.matched += static_cast<std::size_t>((keep[0] != 0) + (keep[1] != 0));
  s.rejected += static_cast<std::size_t>((rejected[0] != 0) + (rejected[1] != 0));
  q = masked(q, keep);
  l.score += q;  // eq. (3.11)
  if (!kGradient) return;
  cx = masked(cx, keep), cy = masked(cy, keep), cz = masked(cz, keep);
  l.gx += cx, l.gy += cy, l.gz += cz;
  l.n[0] += cx * x, l.n[1] += cx * y, l.n[2] += cx * z;
  l.n[3] += cy * x, l.n[4] += cy * y, l.n[5] += cy * z;
  l.n[6] += cz * x, l.n[7] += cz * y, l.n[8] += cz * z;
  if (!kHessian) return;
  a = masked(a, keep), b = masked(b, keep), c = masked(c, keep);
  d = masked(d, keep), e = masked(e, keep), f = masked(f, keep);
  l.p[0] += a, l.p[1] += b, l.p[2] += c, l.p[3] += d, l.p[4] += e, l.p[5] += f;
  // B = C⁻¹[u]×, [u]× = [[0,−uz,uy],[uz,0,−ux],[−uy,ux,0]].
  const v2d b00 = b * z - c * y, b01 = c * x - a * z, b02 = a * y - b * x;
  const v2d b10 = d * z - e * y, b11 = e * x - b * z, b12 = b * y - d * x;
  const v2d b20 = e * z - f * y, b21 = f * x - c * z, b22 = c * y - e * x;
  l.q[0] += b00, l.q[1] += b01, l.q[2] += b02;
  l.q[3] += b10, l.q[4] += b11, l.q[5] += b12;
  l.q[6] += b20, l.q[7] += b21, l.q[8] += b22;
  // S = [u]×ᵀ·B = −[u]×·B (upper triangle).
  l.s[0] += z * b10 - y * b20;
  l.s[1] += z * b11 - y * b21;
  l.s[2] += z * b12 - y * b22;
  l.s[3] += x * b21 - z * b01;
  l.s[4] += x * b22 - z * b02;
  l.s[5] += y * b02 - x * b12;
}

/// s += the lane sums (s is the block's fresh Sums).
void fold(const Lanes& l, Sums& s) {
  s.score += lane_sum(l.score);
  s.g_t += Eigen::Vector3d(lane_sum(l.gx), lane_sum(l.gy), lane_sum(l.gz));
  for (int i = 0; i < 9; ++i) {
    s.N(i / 3, i % 3) += lane_sum(l.n[i]);
    s.Q(i / 3, i % 3) += lane_sum(l.q[i]);
  }
  const int upper[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};
  for (int i = 0; i < 6; ++i) {
    s.P(upper[i][0], upper[i][1]) += lane_sum(l.p[i]);
    s.S(upper[i][0], upper[i][1]) += lane_sum(l.s[i]);
  }
}

template <bool kGradient, bool kHessian>
void block(const NdtGrid& grid, const Eigen::Vector3f* begin, const Eigen::Vector3f* end,
           const Eigen::Matrix3d& R, const Eigen::Vector3d& t, double max_q, Sums& s) {
  alignas(16) double ux[kChunk + 1], uy[kChunk + 1], uz[kChunk + 1];
  int g[kChunk + 1];
  Lanes lanes;
  const v2d tx = pair(t.x(), t.x()), ty = pair(t.y(), t.y()), tz = pair(t.z(), t.z());
  const v2d limit = pair(max_q, max_q);
  const double r00 = R(0, 0), r01 = R(0, 1), r02 = R(0, 2), r10 = R(1, 0), r11 = R(1, 1), r12 = R(1, 2),
               r20 = R(2, 0), r21 = R(2, 1), r22 = R(2, 2);
  for (const Eigen::Vector3f* p = begin; p != end;) {
    int n = 0;
    for (; p != end && n < kChunk; ++p) {
      const double px = p->x(), py = p->y(), pz = p->z();
      const double x = r00 * px + r01 * py + r02 * pz;  // u = R·x
      const double y = r10 * px + r11 * py + r12 * pz;
      const double z = r20 * px + r21 * py + r22 * pz;
      const int cell = grid.lookup(static_cast<float>(x + t.x()), static_cast<float>(y + t.y()),
                                   static_cast<float>(z + t.z()));
      if (cell < 0) continue;
      ux[n] = x, uy[n] = y, uz[n] = z, g[n] = cell;
      ++n;
    }
    if (n % 2 != 0) ux[n] = uy[n] = uz[n] = 0.0, g[n] = -1, ++n;  // the padding lane
    for (int i = 0; i < n; i += 2)
      pair_terms<kGradient, kHessian>(grid, ux + i, uy + i, uz + i, g + i, tx, ty, tz, limit, lanes, s);
  }
  fold(lanes, s);
}

}  // namespace

void mahalanobis_block(const NdtGrid& grid, const Eigen::Vector3f* begin, const Eigen::Vector3f* end,
                       const Eigen::Matrix3d& R, const Eigen::Vector3d& t, double max_q,
                       Derivatives derivatives, Sums& s) {
  if (grid.empty()) return;
  switch (derivatives) {
    case Derivatives::kScore: block<false, false>(grid, begin, end, R, t, max_q, s); break;
    case Derivatives::kGradient: block<true, false>(grid, begin, end, R, t, max_q, s); break;
    case Derivatives::kHessian: block<true, true>(grid, begin, end, R, t, max_q, s); break;
  }
}

}  // namespace sextant::score_detail
