#pragma once
// Operations on a block-sparse information form (Ω, ξ, μ) shared by SEIF and ESEIF (private to
// the module). Variable 0 is the pose, variable k is landmark k−1.
#include <vector>

#include <Eigen/Core>

#include "sextant/filters/filter.hpp"
#include "sextant/filters/seif.hpp"

namespace sextant::detail {

constexpr int kPose = 0;  ///< the pose's variable index (landmark k is variable k + 1)

/// Row/column offsets of each variable inside a gathered dense block (size vars.size() + 1).
std::vector<Eigen::Index> local_offsets(const BlockInformationMatrix& omega, const std::vector<int>& vars);
Eigen::VectorXd gather_vector(const BlockInformationMatrix& omega, const Eigen::VectorXd& v,
                              const std::vector<int>& vars);
void scatter_add_vector(const BlockInformationMatrix& omega, const Eigen::VectorXd& local,
                        const std::vector<int>& vars, Eigen::VectorXd* v);

/// The pose and its neighbours in Ω (the active landmarks), pose first.
std::vector<int> pose_and_neighbours(const BlockInformationMatrix& omega);

/// The motion update of the information form (thesis eq. 4.109) in the constant-time form
/// Ω̄ = Φ − Φ_{:,v} U (I + Φ_vv U)⁻¹ Φ_{v,:}, Φ = (I+A)⁻ᵀ Ω (I+A)⁻¹, ξ̄ = ξ + (Ω̄ − Ω) μ + Ω̄_{:,v} Δ,
/// over the pose and its neighbours only; moves μ_v by Δ = f(μ_v, u) − μ_v (angles not wrapped).
/// ESEIF's "time projection" (Walter et al. 2007, augment x_{t+1} then marginalise x_t) is the
/// same update. Returns kOk, or the status of a singular Jacobian / inner matrix (state unchanged).
StepStatus information_motion_update(const SlamModel& model, BlockInformationMatrix& omega,
                                     Eigen::VectorXd& xi, Eigen::VectorXd& mu, const Eigen::VectorXd& u,
                                     const Eigen::MatrixXd& Q);

/// One measurement z of landmark `landmark` (0-based), linearised at μ (thesis eq. 4.107):
/// Ω += Hᵀ R⁻¹ H, ξ += Hᵀ R⁻¹ (z − h(μ) + H μ) over the pose and the landmark.
void information_measurement(const SlamModel& model, BlockInformationMatrix& omega, Eigen::VectorXd& xi,
                             const Eigen::VectorXd& mu, const Eigen::VectorXd& z, const Eigen::MatrixXd& Rinv,
                             int landmark);

/// Appends the landmark observed as z: the factor m = g(μ_v, z) + G_v (x_v − μ_v) + e,
/// e ~ N(0, G_z R G_zᵀ) (information-form counterpart of thesis eq. 4.68). Returns the new
/// variable, or −1 when G_z R G_zᵀ is singular (state unchanged).
int information_augment(const SlamModel& model, BlockInformationMatrix& omega, Eigen::VectorXd& xi,
                        Eigen::VectorXd& mu, const Eigen::VectorXd& z, const Eigen::MatrixXd& R);

/// The information form of N(x0, P0): Ω = P0⁻¹ stored block-sparse (exact zeros left out),
/// ξ = Ω x0, μ = x0. False when P0 is not positive definite (nothing changed).
bool information_from_moments(const SlamModel& model, const Eigen::VectorXd& x0, const Eigen::MatrixXd& P0,
                              BlockInformationMatrix& omega, Eigen::VectorXd& xi, Eigen::VectorXd& mu);

/// μ_var ← μ_var + δ keeping ξ = Ω μ (angle wrapping, normal renormalisation).
void shift_mean(const BlockInformationMatrix& omega, Eigen::VectorXd& xi, Eigen::VectorXd& mu, int var,
                const Eigen::VectorXd& delta);

/// Wraps the pose angles (var 0) or normalises the landmark (var > 0), keeping ξ = Ω μ.
void normalize_variable(const SlamModel& model, const BlockInformationMatrix& omega, Eigen::VectorXd& xi,
                        Eigen::VectorXd& mu, int var);

/// Solves Ω x = b with a sparse Cholesky factorisation of the whole Ω (its cost grows with the
/// number of links, not with n³). False when Ω is not positive definite.
bool sparse_solve(const BlockInformationMatrix& omega, const Eigen::VectorXd& b, Eigen::VectorXd* x);
/// The covariance of the given variables, (Ω⁻¹)_{vars,vars}, from a sparse Cholesky factorisation
/// (the exact marginal of the information form). Empty matrix when Ω is not positive definite.
Eigen::MatrixXd sparse_marginal(const BlockInformationMatrix& omega, const std::vector<int>& vars);

}  // namespace sextant::detail
