#include "sextant/matchers/cell_covariance.hpp"

#include <algorithm>
#include <cmath>

namespace sextant {

namespace {

/// The upper triangle of a symmetric 3 × 3 matrix: every matrix here is one, or a polynomial in one.
struct Sym {
  double xx, xy, xz, yy, yz, zz;
};

Sym upper_of(const Eigen::Matrix3d& C) {
  return {C(0, 0), C(0, 1), C(0, 2), C(1, 1), C(1, 2), C(2, 2)};
}

Eigen::Matrix3d matrix_of(const Sym& s) {
  Eigen::Matrix3d m;
  m << s.xx, s.xy, s.xz, s.xy, s.yy, s.yz, s.xz, s.yz, s.zz;
  return m;
}

Sym times(const Sym& s, double k) {
  return {k * s.xx, k * s.xy, k * s.xz, k * s.yy, k * s.yz, k * s.zz};
}

Sym plus(const Sym& a, const Sym& b) {
  return {a.xx + b.xx, a.xy + b.xy, a.xz + b.xz, a.yy + b.yy, a.yz + b.yz, a.zz + b.zz};
}

/// ‖S‖_F²: the sum of the squares of all nine entries.
double squared_norm(const Sym& s) {
  return s.xx * s.xx + s.yy * s.yy + s.zz * s.zz + 2.0 * (s.xy * s.xy + s.xz * s.xz + s.yz * s.yz);
}

/// The cofactors of a symmetric matrix (its adjugate, also symmetric).
Sym cofactors(const Sym& s) {
  return {s.yy * s.zz - s.yz * s.yz, s.xz * s.yz - s.xy * s.zz, s.xy * s.yz - s.xz * s.yy,
          s.xx * s.zz - s.xz * s.xz, s.xy * s.xz - s.xx * s.yz, s.xx * s.yy - s.xy * s.xy};
}

double determinant(const Sym& s, const Sym& cof) {
  return s.xx * cof.xx + s.xy * cof.xy + s.xz * cof.xz;
}

Sym inverse(const Sym& s) {
  const Sym cof = cofactors(s);
  return times(cof, 1.0 / determinant(s, cof));
}

/// (S − a I)(S − b I): a polynomial in S, so symmetric; row i of the first times column j of the second.
Sym shifted_product(const Sym& s, double a, double b) {
  const double xa = s.xx - a, ya = s.yy - a, za = s.zz - a;
  const double xb = s.xx - b, yb = s.yy - b, zb = s.zz - b;
  return {xa * xb + s.xy * s.xy + s.xz * s.xz, xa * s.xy + s.xy * yb + s.xz * s.yz,
          xa * s.xz + s.xy * s.yz + s.xz * zb, s.xy * s.xy + ya * yb + s.yz * s.yz,
          s.xy * s.xz + ya * s.yz + s.yz * zb, s.xz * s.xz + s.yz * s.yz + za * zb};
}

Eigen::Vector3d eigenvalues_of(const Sym& s) {
  const double mean = (s.xx + s.yy + s.zz) / 3.0;
  // K = (C − mean I) / scale has trace 0 and entries in [−1, 1]: its characteristic polynomial is
  // λ³ − 3pλ − 2q with p = tr(K²) / 6 and q = det K / 2, whose roots are 2√p cos(θ + 2πk/3) with
  // cos 3θ = q / p^(3/2).
  const double scale = std::max({std::abs(s.xx - mean), std::abs(s.yy - mean), std::abs(s.zz - mean),
                                 std::abs(s.xy), std::abs(s.xz), std::abs(s.yz)});
  if (!(scale > 0.0)) return Eigen::Vector3d::Constant(mean);  // a multiple of I
  const double k = 1.0 / scale;
  const Sym K{k * (s.xx - mean), k * s.xy, k * s.xz, k * (s.yy - mean), k * s.yz, k * (s.zz - mean)};
  const double p = squared_norm(K) / 6.0;
  const double q = 0.5 * determinant(K, cofactors(K));
  // θ ∈ [0, π/3]: 2√p cos θ is the largest root and the other two come in order.
  const double theta = std::atan2(std::sqrt(std::max(p * p * p - q * q, 0.0)), q) / 3.0;
  const double rho = std::sqrt(p), c = std::cos(theta), sn = std::sqrt(3.0) * std::sin(theta);
  return {mean - scale * rho * (c + sn), mean - scale * rho * (c - sn), mean + scale * 2.0 * rho * c};
}

/// C'⁻¹ from C's ascending eigenvalues `l`, for 0 < floor ≤ λ₂.
Sym inflated_inverse(const Sym& C, const Eigen::Vector3d& l, double floor) {
  if (l(1) < floor) {
    // λ₀ and λ₁ raised: C' = floor·I + (λ₂ − floor) P₂, so C'⁻¹ = I / floor + (1/λ₂ − 1/floor) P₂.
    // The coefficient's numerator, floor − λ₂, is at most λ₂ − λ₁ in size.
    const double to_projector = 1.0 / ((l(2) - l(0)) * (l(2) - l(1)));
    Sym inv = times(shifted_product(C, l(0), l(1)), to_projector * ((floor - l(2)) / (l(2) * floor)));
    inv.xx += 1.0 / floor, inv.yy += 1.0 / floor, inv.zz += 1.0 / floor;
    return inv;
  }
  // λ₀ raised: C' = C + (floor − λ₀) P₀, where floor − λ₀ ≤ λ₁ − λ₀ (λ₁ ≥ floor).
  if (l(0) < floor)
    return inverse(
        plus(C, times(shifted_product(C, l(1), l(2)), (floor - l(0)) / ((l(1) - l(0)) * (l(2) - l(0))))));
  return inverse(C);
}

}  // namespace

Eigen::Vector3d symmetric_eigenvalues(const Eigen::Matrix3d& C) {
  return eigenvalues_of(upper_of(C));
}

bool cell_information(const Eigen::Matrix3d& C, double ratio, double least_spread,
                      Eigen::Matrix3d& information) {
  const Sym s = upper_of(C);
  const double squares = squared_norm(s);
  if (!std::isfinite(squares)) return false;  // NaN or ∞ anywhere
  const double trace = s.xx + s.yy + s.zz;
  const Sym cof = cofactors(s);
  const double minors = cof.xx + cof.yy + cof.zz, det = determinant(s, cof);
  // trace, c₂ and det all positive: every eigenvalue is (Descartes' rule of signs), and then
  // λ₀ ≥ λ₀λ₁λ₂ / (λ₀λ₁ + λ₀λ₂ + λ₁λ₂), λ₂ ≤ ‖C‖_F and λ₂ ≥ trace / 3. With det ≥ 10⁻⁸ ‖C‖_F³ (so
  // λ₀ ≥ 10⁻⁸ ‖C‖_F) the rounding errors of det and c₂, a few ε ‖C‖_F³ and ε ‖C‖_F², change neither
  // sign nor bound by more than 10⁻⁶ of their size. Both sides of each bound are squared (‖C‖_F² is
  // `squares`, kept where its cube neither overflows nor underflows): no square root.
  if (squares > 1e-90 && squares < 1e90 && trace > 0.0 && minors > 0.0 && det > 0.0 &&
      det * det >= 1e-16 * squares * squares * squares &&
      (det * ratio) * (det * ratio) >= minors * minors * squares && trace >= 3.0 * least_spread) {
    information = matrix_of(times(cof, 1.0 / det));
    return true;
  }
  const Eigen::Vector3d l = eigenvalues_of(s);
  if (!(l(2) > 0.0) || !(l(2) >= least_spread)) return false;
  information = matrix_of(inflated_inverse(s, l, l(2) / ratio));
  return true;
}

}  // namespace sextant
