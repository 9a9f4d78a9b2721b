#include "sextant/matchers/cell_covariance.hpp"

#include <Eigen/LU>

namespace sextant {

Eigen::Matrix3d inflated_inverse(const Eigen::Matrix3d& C, const Eigen::Vector3d& l, double floor) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  if (l(1) < floor) {
    // λ₀ and λ₁ raised: C' = floor·I + (λ₂ − floor) P₂, so C'⁻¹ = I / floor + (1/λ₂ − 1/floor) P₂.
    // The coefficient's numerator, floor − λ₂, is at most λ₂ − λ₁ in size.
    const Eigen::Matrix3d P2 = (C - l(0) * I) * (C - l(1) * I) / ((l(2) - l(0)) * (l(2) - l(1)));
    return I / floor + ((floor - l(2)) / (l(2) * floor)) * P2;
  }
  Eigen::Matrix3d raised = C;
  // λ₀ raised: C' = C + (floor − λ₀) P₀, where floor − λ₀ ≤ λ₁ − λ₀ (λ₁ ≥ floor).
  if (l(0) < floor)
    raised += ((floor - l(0)) / ((l(1) - l(0)) * (l(2) - l(0)))) * ((C - l(1) * I) * (C - l(2) * I));
  return raised.inverse();  // closed-form cofactors for a 3 × 3 matrix
}

}  // namespace sextant
