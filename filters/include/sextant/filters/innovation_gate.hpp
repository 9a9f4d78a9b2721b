#pragma once
// The innovation (χ²) gate of data association: how far an observation lies from the landmark it
// is associated with, in units of the predicted innovation covariance.
//
//   const double gate = chi_square_quantile(0.999, model.observation_dim());
//   if (innovation_distance(filter, z, R, j) > gate) reject();
//
// ν = z − h(μ_v, μ_j) (z in the predicted sign convention, angles wrapped) and
// S = H Σ Hᵀ + R with H = [∂h/∂x_v, ∂h/∂m_j] at the mean and Σ = filter.joint_covariance({j}):
// the EKF's linearised innovation for every filter, and SEIF's Markov-blanket covariance.
#include <Eigen/Core>

#include "sextant/filters/filter.hpp"

namespace sextant {

/// νᵀ S⁻¹ ν (the normalised innovation squared); +∞ when S is not positive definite or the
/// inputs are not finite.
double innovation_distance(const Filter& filter, const Eigen::VectorXd& z, const Eigen::MatrixXd& R,
                           int landmark);

}  // namespace sextant
