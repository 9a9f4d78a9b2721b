// Score kernels for NDT and ML-NDT. The per-point work is kept small by writing the rotation
// Jacobian in the rotated point u = R·x: ∂(R·x)/∂α = a_α × u with a_α = e_x, a_β = Rx·e_y,
// a_γ = Rx·Ry·e_z (columns of A), and ∂²(R·x)/∂ξi∂ξj = a_i × (a_j × u) for i ≤ j. So each point
// only adds to sums (C⁻¹, C⁻¹[u]×, [u]×ᵀC⁻¹[u]×, C⁻¹e·uᵀ) and A is applied once at the end.
#include "ndt/ndt_score.hpp"

#include "ndt/mahalanobis_kernel.hpp"
#include "ndt/score_sums.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

namespace sextant {

namespace {

constexpr double kNoLimit = std::numeric_limits<double>::infinity();

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

/// The pose in kernel form: R, t and the rotation-axis matrix A = [a_α a_β a_γ].
struct PoseTerms {
  Eigen::Matrix3d R;
  Eigen::Vector3d t;
  Eigen::Matrix3d A;
  explicit PoseTerms(const Vector6d& xi) {
    const Eigen::Matrix3d Rx = Eigen::AngleAxisd(xi(3), Eigen::Vector3d::UnitX()).toRotationMatrix();
    const Eigen::Matrix3d Ry = Eigen::AngleAxisd(xi(4), Eigen::Vector3d::UnitY()).toRotationMatrix();
    R = rotation_from_euler(xi(3), xi(4), xi(5));  // eq. (3.8)
    t = xi.head<3>();
    A.col(0) = Eigen::Vector3d::UnitX();
    A.col(1) = Rx * Eigen::Vector3d::UnitY();
    A.col(2) = Rx * Ry * Eigen::Vector3d::UnitZ();
  }
};

using score_detail::add;
using score_detail::Sums;

/// Runs `block(begin, end, sums)` over the fixed blocks [b·K, min((b+1)·K, n)), K =
/// kScoreBlockPoints, each into its own zeroed Sums, and adds the block sums in block order on
/// the calling thread. The blocks and the order of every addition are the same for every
/// thread count, so the result is bit-identical for 1, 2, … threads; one thread (or a single
/// block) runs the same blocks in turn on the calling thread.
template <class Block>
Sums blocked_sum(std::size_t n, const ScoreThreads& threads, const Block& block) {
  constexpr std::size_t K = kScoreBlockPoints;
  const std::size_t blocks = (n + K - 1) / K;
  Sums total;
  if (threads.concurrency() <= 1 || blocks < 2) {
    for (std::size_t b = 0; b < blocks; ++b) {
      Sums s;
      block(b * K, std::min(n, (b + 1) * K), s);
      add(total, s);
    }
    return total;
  }
  std::vector<Sums> sums(blocks);
  threads.for_each(blocks, [&](std::size_t b) {
    Sums s;  // on this thread's stack, copied out once per block
    block(b * K, std::min(n, (b + 1) * K), s);
    sums[b] = s;
  });
  for (const Sums& s : sums) add(total, s);  // block order, whatever thread summed each block
  return total;
}

/// C⁻¹ from the packed upper triangle.
inline void unpack(const float* ic, double& xx, double& xy, double& xz, double& yy, double& yz, double& zz) {
  xx = ic[0], xy = ic[1], xz = ic[2], yy = ic[3], yz = ic[4], zz = ic[5];
}

/// Adds one point/cell pair. `w` weights the first-order and Gauss–Newton terms, `v` the
/// rank-one term of the Gaussian score. Written out by hand: this is the hot loop.
template <bool kGradient, bool kHessian, bool kOuter>
inline void accumulate(const CellGaussian& cell, const Eigen::Vector3d& u, const Eigen::Vector3d& t, double w,
                       double v, double score_term_scale, bool gaussian, double d2, double max_q, Sums& s) {
  double a, b, c, d, e, f;
  unpack(cell.inv_cov, a, b, c, d, e, f);
  const double ex = u.x() + t.x() - cell.mean[0];  // eq. (3.10)
  const double ey = u.y() + t.y() - cell.mean[1];
  const double ez = u.z() + t.z() - cell.mean[2];
  const double cx = a * ex + b * ey + c * ez;  // C⁻¹e
  const double cy = b * ex + d * ey + e * ez;
  const double cz = c * ex + e * ey + f * ez;
  const double q = ex * cx + ey * cy + ez * cz;  // eᵀC⁻¹e, eq. (3.13)
  if (q > max_q) {  // a rejected correspondence: no terms here, the caller charges it
    ++s.rejected;
    return;
  }
  double weight = w;
  if (gaussian) {
    const double ex_term = std::exp(-0.5 * d2 * q);
    s.score += score_term_scale * ex_term;  // d1·exp(−d2/2·q), eq. (3.6)
    weight = w * ex_term;
    v *= ex_term;
  } else {
    s.score += score_term_scale * q;  // eq. (3.11)
  }
  ++s.matched;
  if (!kGradient) return;
  const double ux = u.x(), uy = u.y(), uz = u.z();
  s.g_t += weight * Eigen::Vector3d(cx, cy, cz);
  const double wcx = weight * cx, wcy = weight * cy, wcz = weight * cz;
  s.N(0, 0) += wcx * ux, s.N(0, 1) += wcx * uy, s.N(0, 2) += wcx * uz;
  s.N(1, 0) += wcy * ux, s.N(1, 1) += wcy * uy, s.N(1, 2) += wcy * uz;
  s.N(2, 0) += wcz * ux, s.N(2, 1) += wcz * uy, s.N(2, 2) += wcz * uz;
  if (!kHessian) return;
  // P += w·C⁻¹ (symmetric, upper triangle here, mirrored at the end).
  s.P(0, 0) += weight * a, s.P(0, 1) += weight * b, s.P(0, 2) += weight * c;
  s.P(1, 1) += weight * d, s.P(1, 2) += weight * e, s.P(2, 2) += weight * f;
  // B = C⁻¹[u]×, columns: C⁻¹(e_k × u) … [u]× = [[0,−uz,uy],[uz,0,−ux],[−uy,ux,0]].
  const double b00 = b * uz - c * uy, b01 = -a * uz + c * ux, b02 = a * uy - b * ux;
  const double b10 = d * uz - e * uy, b11 = -b * uz + e * ux, b12 = b * uy - d * ux;
  const double b20 = e * uz - f * uy, b21 = -c * uz + f * ux, b22 = c * uy - e * ux;
  s.Q(0, 0) += weight * b00, s.Q(0, 1) += weight * b01, s.Q(0, 2) += weight * b02;
  s.Q(1, 0) += weight * b10, s.Q(1, 1) += weight * b11, s.Q(1, 2) += weight * b12;
  s.Q(2, 0) += weight * b20, s.Q(2, 1) += weight * b21, s.Q(2, 2) += weight * b22;
  // S = [u]×ᵀ·B = −[u]×·B (symmetric, upper triangle).
  s.S(0, 0) += weight * (uz * b10 - uy * b20);
  s.S(0, 1) += weight * (uz * b11 - uy * b21);
  s.S(0, 2) += weight * (uz * b12 - uy * b22);
  s.S(1, 1) += weight * (-uz * b01 + ux * b21);
  s.S(1, 2) += weight * (-uz * b02 + ux * b22);
  s.S(2, 2) += weight * (uy * b02 - ux * b12);
  if (kOuter) {
    Vector6d m;
    m << cx, cy, cz, uy * cz - uz * cy, uz * cx - ux * cz, ux * cy - uy * cx;
    s.outer.noalias() += v * m * m.transpose();
  }
}

/// Multiplies the derivative sums by `factor`. With factor 2 this is exact (a power of two), so
/// 2·Σx is bit-identical to Σ2x: the Mahalanobis kernel sums unweighted terms and doubles once.
void scale_derivatives(Sums& s, double factor) {
  s.g_t *= factor;
  s.N *= factor;
  s.P *= factor;
  s.Q *= factor;
  s.S *= factor;
}

/// Maps the sums to ξ: g = Bᵀ·g', H = Bᵀ·H'·B + second-order terms, B = blockdiag(I, A).
ScoreEvaluation finish(Sums& s, const PoseTerms& pose, Derivatives derivatives, bool mahalanobis) {
  ScoreEvaluation out;
  out.score = s.score;
  out.matched = s.matched;
  out.rejected = s.rejected;
  if (derivatives == Derivatives::kScore) return out;
  const Eigen::Matrix3d& A = pose.A;
  const Eigen::Matrix3d& N = s.N;
  const Eigen::Vector3d w(N(2, 1) - N(1, 2), N(0, 2) - N(2, 0), N(1, 0) - N(0, 1));  // Σ u × C⁻¹e
  out.gradient.head<3>() = s.g_t;
  out.gradient.tail<3>() = A.transpose() * w;
  if (derivatives != Derivatives::kHessian) return out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < i; ++j) s.P(i, j) = s.P(j, i), s.S(i, j) = s.S(j, i);
  Matrix6d first;
  first.topLeftCorner<3, 3>() = s.P;
  first.topRightCorner<3, 3>() = -s.Q * A;
  first.bottomLeftCorner<3, 3>() = first.topRightCorner<3, 3>().transpose();
  first.bottomRightCorner<3, 3>() = A.transpose() * s.S * A;
  // Second-order terms eᵀC⁻¹·∂²e/∂ξi∂ξj = Σ_kl ([a_i]×[a_j]×)_kl N_kl, i ≤ j (eq. 3.15).
  Matrix6d second = Matrix6d::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) {
      const double value = (skew(A.col(i)) * skew(A.col(j))).cwiseProduct(N).sum();
      second(3 + i, 3 + j) = second(3 + j, 3 + i) = value;
    }
  }
  Matrix6d B = Matrix6d::Identity();
  B.bottomRightCorner<3, 3>() = A;
  out.hessian = first + second + B.transpose() * s.outer * B;
  if (mahalanobis) out.gauss_newton = first;
  return out;
}

template <bool kGradient, bool kHessian>
void gaussian_loop(const NdtGrid& grid, const Eigen::Vector3f* begin, const Eigen::Vector3f* end,
                   const PoseTerms& pose, const GaussianScoreParams& p, bool trilinear, Sums& s) {
  // f = d1·exp(−d2/2·q): ∂f = −d1·d2·exp(·)·eᵀC⁻¹∂e, ∂²f = −d1·d2·exp(·)·(∂eᵀC⁻¹∂e + eᵀC⁻¹∂²e
  // − d2·(eᵀC⁻¹∂e)(eᵀC⁻¹∂e)ᵀ).
  const double w = -p.d1 * p.d2;
  const double v = p.d1 * p.d2 * p.d2;
  const double edge = grid.cell_edge();
  const Eigen::Vector3d origin = grid.origin();
  for (const Eigen::Vector3f* point = begin; point != end; ++point) {
    const Eigen::Vector3f& pf = *point;
    const Eigen::Vector3d u = pose.R * pf.cast<double>();
    const Eigen::Vector3d x = u + pose.t;
    if (!trilinear) {
      const int g =
          grid.lookup(static_cast<float>(x.x()), static_cast<float>(x.y()), static_cast<float>(x.z()));
      if (g >= 0)
        accumulate<kGradient, kHessian, kHessian>(grid.gaussian(g), u, pose.t, w, v, p.d1, true, p.d2,
                                                  kNoLimit, s);
      continue;
    }
    // Trilinear: the 8 cells whose centres enclose x, weights from the position between centres.
    const Eigen::Vector3d f = (x - origin) / edge - Eigen::Vector3d::Constant(0.5);
    if (!f.allFinite()) continue;
    const Eigen::Vector3d lower = f.array().floor();
    if ((lower.array().abs() > 1e9).any()) continue;
    const Eigen::Vector3d frac = f - lower;
    const int ix = static_cast<int>(lower.x()), iy = static_cast<int>(lower.y()),
              iz = static_cast<int>(lower.z());
    bool any = false;
    for (int corner = 0; corner < 8; ++corner) {
      const int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
      const int g = grid.at(ix + dx, iy + dy, iz + dz);
      if (g < 0) continue;
      const double weight =
          (dx ? frac.x() : 1 - frac.x()) * (dy ? frac.y() : 1 - frac.y()) * (dz ? frac.z() : 1 - frac.z());
      if (weight <= 0.0) continue;
      const std::size_t before = s.matched;
      accumulate<kGradient, kHessian, kHessian>(grid.gaussian(g), u, pose.t, weight * w, weight * v,
                                                weight * p.d1, true, p.d2, kNoLimit, s);
      s.matched = before;
      any = true;
    }
    if (any) ++s.matched;
  }
}

}  // namespace

struct ScoreThreads::Arena {
  tbb::task_arena arena;
  explicit Arena(int concurrency) : arena(concurrency) {}  // initialised on first use
};

ScoreThreads::ScoreThreads(int threads) {
  if (threads == 1) return;
  // More threads than TBB allows would only idle (and make TBB warn).
  std::size_t limit = tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
  if (threads > 0) limit = std::min(limit, static_cast<std::size_t>(threads));
  concurrency_ = static_cast<int>(std::max<std::size_t>(limit, 1));
  if (concurrency_ > 1) arena_ = std::make_unique<Arena>(concurrency_);
}

ScoreThreads::~ScoreThreads() = default;

void ScoreThreads::for_each(std::size_t count, const std::function<void(std::size_t)>& body) const {
  if (!arena_) {
    for (std::size_t i = 0; i < count; ++i) body(i);
    return;
  }
  arena_->arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, count, 1),
        [&](const tbb::blocked_range<std::size_t>& range) {
          for (std::size_t i = range.begin(); i != range.end(); ++i) body(i);
        },
        tbb::simple_partitioner());
  });
}

GaussianScoreParams GaussianScoreParams::from_outlier_ratio(double outlier_ratio, double cell_edge) {
  const double c1 = 10.0 * (1.0 - outlier_ratio);
  const double c2 = outlier_ratio / (cell_edge * cell_edge * cell_edge);
  const double d3 = -std::log(c2);
  GaussianScoreParams p;
  p.d1 = -std::log(c1 + c2) - d3;
  p.d2 = -2.0 * std::log((-std::log(c1 * std::exp(-0.5) + c2) - d3) / p.d1);
  return p;
}

ScoreEvaluation mahalanobis_score(const NdtGrid& grid, const PointCloud& input, const Vector6d& xi,
                                  Derivatives derivatives, double max_distance, const ScoreThreads& threads) {
  const PoseTerms pose(xi);
  if (grid.empty() || !xi.allFinite()) {
    Sums none;
    return finish(none, pose, Derivatives::kScore, true);
  }
  const Eigen::Vector3f* points = input.points().data();
  // s_k = eᵀC⁻¹e, g_k = 2eᵀC⁻¹∂e/∂ξ, H_k = 2(∂eᵀC⁻¹∂e + eᵀC⁻¹∂²e), eqs. (3.13)–(3.15): the
  // kernel sums unweighted terms, the factor 2 is applied once to the sums (exact).
  Sums s = blocked_sum(input.size(), threads, [&](std::size_t begin, std::size_t end, Sums& block) {
    score_detail::mahalanobis_block(grid, points + begin, points + end, pose.R, pose.t, max_distance,
                                    derivatives, block);
  });
  scale_derivatives(s, 2.0);
  return finish(s, pose, derivatives, true);
}

ScoreEvaluation gaussian_score(const NdtGrid& grid, const PointCloud& input, const Vector6d& xi,
                               const GaussianScoreParams& params, bool trilinear, Derivatives derivatives,
                               const ScoreThreads& threads) {
  const PoseTerms pose(xi);
  if (grid.empty() || !xi.allFinite()) {
    Sums none;
    return finish(none, pose, Derivatives::kScore, false);
  }
  const Eigen::Vector3f* points = input.points().data();
  Sums s = blocked_sum(input.size(), threads, [&](std::size_t begin, std::size_t end, Sums& block) {
    switch (derivatives) {
      case Derivatives::kScore:
        gaussian_loop<false, false>(grid, points + begin, points + end, pose, params, trilinear, block);
        break;
      case Derivatives::kGradient:
        gaussian_loop<true, false>(grid, points + begin, points + end, pose, params, trilinear, block);
        break;
      case Derivatives::kHessian:
        gaussian_loop<true, true>(grid, points + begin, points + end, pose, params, trilinear, block);
        break;
    }
  });
  return finish(s, pose, derivatives, false);
}

}  // namespace sextant
