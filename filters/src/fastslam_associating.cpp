// FastSLAM 2.0 with per-particle data association (Montemerlo, Thrun, Koller and Wegbreit,
// IJCAI 2003, §3: "each particle makes its own data association decision"): per particle, the
// associator decides at the particle's predicted pose against the particle's own landmark EKFs;
// the known observations drive the FastSLAM 2.0 proposal, landmark updates and weight
// (fastslam_update.cpp), the new ones become landmarks of that particle alone at its sampled pose
// (eqs. 4.57–4.58, 4.67 at a known pose), and every observation no known landmark explains
// multiplies the weight by p0 (Montemerlo's likelihood of a new feature).
#include <Eigen/Cholesky>

#include <cmath>
#include <limits>

#include "sextant/filters/covariance.hpp"
#include "sextant/filters/fastslam.hpp"
#include "step_checks.hpp"

namespace sextant {

// ν = z − g(ŝ, μ_θ) and S = G_s P_t G_sᵀ + G_θ Σ_θ G_θᵀ + R: one observation's block of the
// proposal's innovation (fastslam_update.cpp, Montemerlo et al. 2003, §3), P_t the pending pose
// covariance (zero once sampled).
double particle_innovation_distance(const SlamModel& model, const FastSlamParticle& particle,
                                    const Eigen::VectorXd& z, const Eigen::MatrixXd& R, int landmark) {
  constexpr double kFar = std::numeric_limits<double>::infinity();
  if (landmark < 0 || landmark >= particle.map.size()) return kFar;
  const LandmarkEkf& theta = particle.map.get(landmark);
  const Eigen::VectorXd predicted = model.observe(particle.pose, theta.mean);
  Eigen::VectorXd nu = model.align_observation(z, predicted) - predicted;
  wrap_entries(nu, model.observation_angles());
  const Eigen::MatrixXd Gtheta = model.observe_jacobian_landmark(particle.pose, theta.mean);
  Eigen::MatrixXd S = Gtheta * theta.covariance * Gtheta.transpose() + R;
  if (particle.pending) {
    const Eigen::MatrixXd Gs = model.observe_jacobian_pose(particle.pose, theta.mean);
    S += Gs * particle.pose_covariance * Gs.transpose();
  }
  if (!nu.allFinite() || !S.allFinite()) return kFar;
  const Eigen::LLT<Eigen::MatrixXd> llt(symmetrized(S));
  if (llt.info() != Eigen::Success) return kFar;
  return nu.dot(llt.solve(nu));
}

StepStatus FastSlam::associate_particle(FastSlamParticle& particle, const std::vector<Eigen::VectorXd>& zs,
                                        const Eigen::MatrixXd& R, const ParticleAssociator& associator,
                                        const ParticleDecision& decision) {
  StepStatus status = StepStatus::kOk;
  std::vector<Eigen::VectorXd> known;
  std::vector<int> landmarks;
  std::vector<std::size_t> observation_ids, fresh;
  std::size_t unexplained = 0;
  for (std::size_t i = 0; i < zs.size(); ++i) {
    const int j = decision.landmarks[i];
    if (j >= 0 && j < particle.map.size()) {
      known.push_back(zs[i]);
      landmarks.push_back(j);
      observation_ids.push_back(i);
      continue;
    }
    if (j == kNewLandmark) fresh.push_back(i);
    if (j != kNewLandmark && j != kUnexplained) status = StepStatus::kInvalidInput;  // treated as unexplained
    ++unexplained;
  }
  // The known observations: proposal, landmark EKFs, weight (eqs. of fastslam_update.cpp).
  const StepStatus updated =
      known.empty() ? sample_pose(particle)
                    : update_particle(particle, known, R, landmarks, &associator, &observation_ids);
  if (status == StepStatus::kOk) status = updated;
  particle.log_weight += static_cast<double>(unexplained) * associator.unexplained_log_likelihood();
  // The new ones: landmarks of this particle at its sampled pose, m = g(s, z), G_z R G_zᵀ
  // (eqs. 4.57–4.58, 4.67), appended to its own copy-on-write map, O(log M) each.
  for (std::size_t i : fresh) {
    const Eigen::MatrixXd Gz = model_->augment_jacobian_observation(particle.pose, zs[i]);
    LandmarkEkf ekf{model_->augment(particle.pose, zs[i]), symmetrized(Gz * R * Gz.transpose()), nullptr};
    model_->normalize_landmark(ekf.mean);
    if (status == StepStatus::kOk && !(ekf.mean.allFinite() && is_positive_definite(ekf.covariance)))
      status = StepStatus::kNotPositiveDefinite;
    ekf.attachment = associator.attach(particle.pose, i, ekf);
    particle.map.push_back(std::move(ekf), &counters_.map);
  }
  return status;
}

ParticleAssociationStep FastSlam::update_associating(const std::vector<Eigen::VectorXd>& zs,
                                                     const Eigen::MatrixXd& R,
                                                     const ParticleAssociator& associator) {
  detail::StepClock clock;
  ParticleAssociationStep out;
  bool valid = !particles_.empty();
  for (const Eigen::VectorXd& z : zs) valid = valid && detail::valid_observation(*model_, z, R);
  if (!valid) {
    out.result = finish(StepStatus::kInvalidInput, clock.seconds());
    return out;
  }
  per_particle_ = true;
  const std::vector<double> before = log_weights();
  std::vector<ParticleDecision> decisions(particles_.size());
  std::vector<int> sizes(particles_.size());
  StepStatus status = StepStatus::kOk;
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    FastSlamParticle& particle = particles_[i];
    ParticleDecision& decision = decisions[i];
    decision = associator.associate(particle);
    out.candidates_tested += decision.candidates_tested;
    if (decision.landmarks.size() != zs.size()) {
      decision.landmarks.assign(zs.size(), kUnexplained);
      if (status == StepStatus::kOk) status = StepStatus::kInvalidInput;
    }
    sizes[i] = particle.map.size();
    const StepStatus s = associate_particle(particle, zs, R, associator, decision);
    if (s != StepStatus::kOk && status == StepStatus::kOk) status = s;
  }
  // The reported decision is the highest-weight particle's, before resampling keeps a copy of it.
  const std::size_t best = best_particle();
  int next = sizes[best];
  out.observation_landmark.assign(zs.size(), -1);
  for (std::size_t i = 0; i < zs.size(); ++i) {
    const int j = decisions[best].landmarks[i];
    if (j >= 0) {
      out.observation_landmark[i] = j;
      ++out.matched;
    } else if (j == kNewLandmark) {
      out.observation_landmark[i] = next++;
      ++out.augmented;
    }
  }
  out.gated = decisions[best].gated;
  if (!zs.empty()) reweight(before);
  representative_ = zs.empty() ? best_particle() : representative_;
  out.representative = representative_;
  out.n_eff = last_update_n_eff_;
  out.result = finish(status, clock.seconds());
  return out;
}

}  // namespace sextant
