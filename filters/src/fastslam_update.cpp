// The FastSLAM 2.0 measurement update (Montemerlo, Thrun, Koller and Wegbreit, IJCAI 2003, §3),
// written with the paper's symbols: ŝ the predicted pose with covariance P_t (here G_u Q G_uᵀ,
// fastslam.cpp), θ a landmark with EKF (μ_θ, Σ_θ), g the observation model (eq. 4.64),
// G_s = ∂g/∂s and G_θ = ∂g/∂θ its Jacobians (eq. 4.65), R_t the observation noise.
#include <Eigen/Cholesky>

#include <cmath>
#include <limits>
#include <map>

#include "sextant/filters/covariance.hpp"
#include "sextant/filters/fastslam.hpp"
#include "sextant/filters/particle_weights.hpp"
#include "step_checks.hpp"

namespace sextant {
namespace {

constexpr double kLog2Pi = 1.8378770664093454836;

/// Innovation ν = z − g(s, μ_θ), with z in the predicted sign convention and angles wrapped.
Eigen::VectorXd observation_innovation(const SlamModel& model, const Eigen::VectorXd& z,
                                       const Eigen::VectorXd& pose, const Eigen::VectorXd& landmark) {
  const Eigen::VectorXd predicted = model.observe(pose, landmark);
  Eigen::VectorXd nu = model.align_observation(z, predicted) - predicted;
  wrap_entries(nu, model.observation_angles());
  return nu;
}

/// One landmark EKF update at a known pose (the pose is the particle's sampled one):
/// K = Σ_θ G_θᵀ S⁻¹, S = G_θ Σ_θ G_θᵀ + R_t, μ_θ += K ν, Σ_θ −= K S Kᵀ
/// (Montemerlo et al. 2003, §3, the landmark update; the EKF of eqs. 4.65–4.66 restricted to θ).
bool update_landmark(const SlamModel& model, const Eigen::VectorXd& pose, const Eigen::VectorXd& z,
                     const Eigen::MatrixXd& R, LandmarkEkf& ekf) {
  const Eigen::VectorXd nu = observation_innovation(model, z, pose, ekf.mean);
  const Eigen::MatrixXd H = model.observe_jacobian_landmark(pose, ekf.mean);
  const Eigen::MatrixXd PHt = ekf.covariance * H.transpose();
  const Eigen::LLT<Eigen::MatrixXd> llt(symmetrized(H * PHt + R));
  if (llt.info() != Eigen::Success) return false;
  const Eigen::MatrixXd K = llt.solve(PHt.transpose()).transpose();
  ekf.mean += K * nu;
  ekf.covariance = symmetrized(ekf.covariance - K * PHt.transpose());
  model.normalize_landmark(ekf.mean);
  return ekf.mean.allFinite() && ekf.covariance.allFinite();
}

}  // namespace

// Per particle, with the observations of each landmark stacked (a landmark may be observed more
// than once in a step; its observations are then correlated through Σ_θ):
//   ν = z − ẑ,  ẑ = g(ŝ, μ_θ)                               (linearised at the predicted pose)
//   Q = R_t ⊕ … + G_θ Σ_θ G_θᵀ (per landmark)                 Montemerlo's Q_t, stacked
//   S = G_s P_t G_sᵀ + Q                                       the weight's L_t
//   Σ_s = [G_sᵀ Q⁻¹ G_s + P_t⁻¹]⁻¹ = P_t − K S Kᵀ,  K = P_t G_sᵀ S⁻¹   (the proposal covariance,
//   μ_s = ŝ + Σ_s G_sᵀ Q⁻¹ ν = ŝ + K ν                          by the matrix inversion lemma:
//                                                              P_t may be singular)
//   s ~ N(μ_s, Σ_s); each observed landmark's EKF is then updated at s;
//   log w += log N(ν; 0, S)                                    the importance weight.
// In a linear-Gaussian model this proposal is p(s_t | s_{t−1}, z_t, map) and the weight
// p(z_t | s_{t−1}, map): the exact optimal proposal.
StepStatus FastSlam::update_particle(FastSlamParticle& particle, const std::vector<Eigen::VectorXd>& zs,
                                     const Eigen::MatrixXd& R, const std::vector<int>& associations,
                                     const ParticleAssociator* attach,
                                     const std::vector<std::size_t>* observation_ids) {
  const int p = model_->pose_dim(), od = model_->observation_dim();
  const Eigen::Index m = static_cast<Eigen::Index>(zs.size()) * od;
  const Eigen::VectorXd& s_hat = particle.pose;
  const Eigen::MatrixXd P = particle.pending ? particle.pose_covariance : Eigen::MatrixXd::Zero(p, p);

  std::map<int, std::vector<Eigen::Index>> by_landmark;  // landmark → its observations
  for (std::size_t i = 0; i < zs.size(); ++i)
    by_landmark[associations[i]].push_back(static_cast<Eigen::Index>(i));
  Eigen::VectorXd nu(m);
  Eigen::MatrixXd Gs(m, p);
  Eigen::MatrixXd Q = block_diagonal(R, static_cast<int>(zs.size()));
  for (const auto& [j, observations] : by_landmark) {
    const LandmarkEkf& theta = particle.map.get(j);
    const Eigen::MatrixXd Gtheta = model_->observe_jacobian_landmark(s_hat, theta.mean);
    const Eigen::MatrixXd Gs_j = model_->observe_jacobian_pose(s_hat, theta.mean);
    const Eigen::MatrixXd landmark_part = Gtheta * theta.covariance * Gtheta.transpose();
    for (Eigen::Index a : observations) {
      nu.segment(a * od, od) =
          observation_innovation(*model_, zs[static_cast<std::size_t>(a)], s_hat, theta.mean);
      Gs.middleRows(a * od, od) = Gs_j;
      for (Eigen::Index b : observations) Q.block(a * od, b * od, od, od) += landmark_part;
    }
  }
  const Eigen::MatrixXd PGt = P * Gs.transpose();
  const Eigen::LLT<Eigen::MatrixXd> llt(symmetrized(Gs * PGt + Q));
  if (llt.info() != Eigen::Success || !nu.allFinite()) {
    particle.log_weight = -std::numeric_limits<double>::infinity();
    sample_pose(particle);
    return StepStatus::kSingularInnovation;
  }
  const Eigen::MatrixXd K = llt.solve(PGt.transpose()).transpose();
  const Eigen::VectorXd proposal_mean = s_hat + K * nu;
  const Eigen::MatrixXd proposal_covariance = symmetrized(P - K * PGt.transpose());
  const Eigen::VectorXd whitened = llt.matrixL().solve(nu);
  const double log_det = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
  const double log_likelihood = -0.5 * (whitened.squaredNorm() + log_det + static_cast<double>(m) * kLog2Pi);

  Eigen::VectorXd s;
  if (!draw_gaussian(proposal_mean, proposal_covariance, rng_, s)) {
    particle.log_weight = -std::numeric_limits<double>::infinity();
    return StepStatus::kCholeskyFailed;
  }
  wrap_entries(s, model_->pose_angles());
  particle.pose = s;
  particle.pose_covariance.setZero(p, p);
  particle.pending = false;
  particle.log_weight += log_likelihood;

  for (const auto& [j, observations] : by_landmark) {
    LandmarkEkf theta = particle.map.get(j);
    for (Eigen::Index a : observations)
      if (!update_landmark(*model_, s, zs[static_cast<std::size_t>(a)], R, theta))
        return StepStatus::kSingularInnovation;
    if (attach)  // the caller's data follows the updated EKF (one write per landmark)
      for (Eigen::Index a : observations)
        theta.attachment = attach->attach(s, (*observation_ids)[static_cast<std::size_t>(a)], theta);
    particle.map.set(j, std::move(theta), &counters_.map);  // copy-on-write: siblings keep theirs
  }
  return StepStatus::kOk;
}

// Every particle's proposal, landmark updates and weight; the weights are normalised in log
// space (particle_weights.hpp) and the set is resampled when N_eff < threshold · N.
StepResult FastSlam::update(const std::vector<Eigen::VectorXd>& zs, const Eigen::MatrixXd& R,
                            const std::vector<int>& associations) {
  detail::StepClock clock;
  if (particles_.empty() || per_particle_ ||
      !detail::valid_observations(*model_, landmarks_, zs, R, associations))
    return finish(StepStatus::kInvalidInput, clock.seconds());
  if (zs.empty()) return finish(StepStatus::kOk, clock.seconds());
  const std::vector<double> before = log_weights();
  StepStatus status = StepStatus::kOk;
  for (FastSlamParticle& particle : particles_) {
    const StepStatus s = update_particle(particle, zs, R, associations);
    if (s != StepStatus::kOk && status == StepStatus::kOk) status = s;
  }
  reweight(before);
  return finish(status, clock.seconds());
}

}  // namespace sextant
