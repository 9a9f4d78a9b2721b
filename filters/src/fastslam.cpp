// FastSLAM 2.0: settings, initialisation, motion update, augmentation and resampling. The
// measurement update (proposal, landmark EKFs, weights) is in fastslam_update.cpp, the Filter's
// moments of the particle set in fastslam_moments.cpp.
#include "sextant/filters/fastslam.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "sextant/core/checked_settings.hpp"
#include "sextant/filters/covariance.hpp"
#include "sextant/filters/particle_weights.hpp"
#include "step_checks.hpp"

namespace sextant {

bool FastSlamSettings::valid(std::string* why) const {
  const char* problem = nullptr;
  if (particles < 1 || particles > 1000000)
    problem = "particles must lie in [1, 1e6]";
  else if (!(resample_threshold >= 0.0 && resample_threshold <= 1.0))
    problem = "resample_threshold must lie in [0, 1] (a fraction of the particle count)";
  if (problem && why) *why = problem;
  return problem == nullptr;
}

bool draw_gaussian(const Eigen::VectorXd& mean, const Eigen::MatrixXd& covariance, Rng& rng,
                   Eigen::VectorXd& out) {
  if (!mean.allFinite() || !covariance.allFinite() || covariance.rows() != mean.size()) return false;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(symmetrized(covariance));
  if (eig.info() != Eigen::Success) return false;
  Eigen::VectorXd xi(mean.size());
  for (Eigen::Index k = 0; k < xi.size(); ++k) xi[k] = rng.normal();
  // x = μ + V Λ^{1/2} ξ: (V Λ^{1/2})(V Λ^{1/2})ᵀ = Σ.
  const Eigen::VectorXd root = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  out = mean + eig.eigenvectors() * root.cwiseProduct(xi);
  return out.allFinite();
}

FastSlam::FastSlam(std::shared_ptr<const SlamModel> model, FastSlamSettings settings, std::uint64_t seed)
    : model_(std::move(model)), s_(checked(settings, "fastslam2")), rng_(seed) {}

std::string FastSlam::approximation() const {
  std::ostringstream out;
  out << "Rao-Blackwellised particles (FastSLAM 2.0): N = " << s_.particles
      << ", proposal linearised at the predicted pose, per-landmark EKFs, systematic resampling when "
         "N_eff < "
      << s_.resample_threshold << " N";
  return out.str();
}

StepResult FastSlam::finish(StepStatus status, double seconds) {
  mean_cache_.resize(0);
  return record(status, seconds);
}

// Poses from N(x0_v, P0_vv); landmark j from its Gaussian conditioned on the drawn pose,
// μ_j + P_jv P_vv⁺ (s − x0_v) with covariance P_jj − P_jv P_vv⁺ P_vj (diagonal blocks only).
StepResult FastSlam::initialize(const Eigen::VectorXd& x0, const Eigen::MatrixXd& P0) {
  detail::StepClock clock;
  if (!detail::valid_state(*model_, x0, P0)) return finish(StepStatus::kInvalidInput, clock.seconds());
  const int p = model_->pose_dim(), l = model_->landmark_dim();
  const int count = landmark_count(*model_, x0.size());
  const Eigen::Index rest = x0.size() - p;
  const Eigen::MatrixXd Pvv = P0.topLeftCorner(p, p);
  // P_mv P_vv⁺ (minimal-norm solve: P_vv may be singular); no landmarks, no gain (Eigen's solve of
  // an empty right-hand side binds a reference to its null data).
  const Eigen::MatrixXd gain =
      rest == 0 ? Eigen::MatrixXd(0, p)
                : Eigen::MatrixXd(Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(Pvv)
                                      .solve(P0.bottomLeftCorner(rest, p).transpose())
                                      .transpose());
  const Eigen::MatrixXd conditional =
      P0.bottomRightCorner(rest, rest) - gain * P0.bottomLeftCorner(rest, p).transpose();
  StepStatus status = StepStatus::kOk;
  particles_.assign(static_cast<std::size_t>(s_.particles), FastSlamParticle{});
  for (FastSlamParticle& particle : particles_) {
    if (!draw_gaussian(x0.head(p), Pvv, rng_, particle.pose)) status = StepStatus::kCholeskyFailed;
    wrap_entries(particle.pose, model_->pose_angles());
    particle.pose_covariance = Eigen::MatrixXd::Zero(p, p);
    particle.log_weight = -std::log(static_cast<double>(s_.particles));
    const Eigen::VectorXd shift = gain * state_difference(*model_, particle.pose, x0.head(p));
    for (int j = 0; j < count; ++j) {
      LandmarkEkf ekf{x0.segment(p + j * l, l) + shift.segment(j * l, l),
                      symmetrized(conditional.block(j * l, j * l, l, l))};
      model_->normalize_landmark(ekf.mean);
      particle.map.push_back(std::move(ekf), &counters_.map);
    }
  }
  landmarks_ = count;
  last_update_n_eff_ = static_cast<double>(s_.particles);
  return finish(status, clock.seconds());
}

// Motion update per particle, eq. (4.72) linearised in the control: the pending pose Gaussian
// N(f(μ, u), F Σ Fᵀ + G_u Q G_uᵀ) (Σ = 0 for a sampled pose). FastSLAM 2.0 samples it only in
// the update, from the proposal that includes the observations (Montemerlo et al. 2003, §3).
StepResult FastSlam::predict(const Eigen::VectorXd& u, const Eigen::MatrixXd& Q) {
  detail::StepClock clock;
  if (!detail::valid_control(*model_, u, Q) || particles_.empty())
    return finish(StepStatus::kInvalidInput, clock.seconds());
  StepStatus status = StepStatus::kOk;
  for (FastSlamParticle& particle : particles_) {
    const Eigen::MatrixXd F = model_->process_jacobian_pose(particle.pose, u);
    const Eigen::MatrixXd G = model_->process_jacobian_control(particle.pose, u);
    Eigen::MatrixXd P = G * Q * G.transpose();
    if (particle.pending) P += F * particle.pose_covariance * F.transpose();
    particle.pose = model_->process(particle.pose, u);
    wrap_entries(particle.pose, model_->pose_angles());
    particle.pose_covariance = symmetrized(P);
    particle.pending = true;
    if (!particle.pose.allFinite() || !P.allFinite()) status = StepStatus::kNotPositiveDefinite;
  }
  return finish(status, clock.seconds());
}

StepStatus FastSlam::sample_pose(FastSlamParticle& particle) {
  if (!particle.pending) return StepStatus::kOk;
  Eigen::VectorXd pose;
  if (!draw_gaussian(particle.pose, particle.pose_covariance, rng_, pose)) return StepStatus::kCholeskyFailed;
  wrap_entries(pose, model_->pose_angles());
  particle.pose = pose;
  particle.pose_covariance.setZero();
  particle.pending = false;
  return StepStatus::kOk;
}

// A new landmark in every particle, at that particle's pose: m = g(s, z) (eqs. 4.57–4.58) with
// covariance G_z R G_zᵀ (eq. 4.67 with the pose known: FastSLAM's landmark initialisation,
// Montemerlo et al. 2003, §3). The importance weight does not change.
StepResult FastSlam::augment(const Eigen::VectorXd& z, const Eigen::MatrixXd& R) {
  detail::StepClock clock;
  if (!detail::valid_observation(*model_, z, R) || particles_.empty() || per_particle_)
    return finish(StepStatus::kInvalidInput, clock.seconds());
  StepStatus status = StepStatus::kOk;
  for (FastSlamParticle& particle : particles_) {
    const StepStatus sampled = sample_pose(particle);
    if (sampled != StepStatus::kOk && status == StepStatus::kOk) status = sampled;
    const Eigen::MatrixXd Gz = model_->augment_jacobian_observation(particle.pose, z);
    LandmarkEkf ekf{model_->augment(particle.pose, z), symmetrized(Gz * R * Gz.transpose())};
    model_->normalize_landmark(ekf.mean);
    if (status == StepStatus::kOk && !(ekf.mean.allFinite() && is_positive_definite(ekf.covariance)))
      status = StepStatus::kNotPositiveDefinite;
    particle.map.push_back(std::move(ekf), &counters_.map);
  }
  ++landmarks_;
  return finish(status, clock.seconds());
}

std::vector<double> FastSlam::log_weights() const {
  std::vector<double> lw;
  lw.reserve(particles_.size());
  for (const FastSlamParticle& particle : particles_) lw.push_back(particle.log_weight);
  return lw;
}

void FastSlam::set_log_weights(const std::vector<double>& log_weights) {
  for (std::size_t i = 0; i < particles_.size(); ++i) particles_[i].log_weight = log_weights[i];
}

std::vector<double> FastSlam::weights() const {
  return weights_from_log(log_weights());
}

double FastSlam::effective_sample_size() const {
  return sextant::effective_sample_size(log_weights());
}

int FastSlam::num_landmarks() const {
  if (per_particle_ && representative_ < particles_.size()) return particles_[representative_].map.size();
  return landmarks_;
}

std::size_t FastSlam::best_particle() const {
  const std::vector<double> lw = log_weights();
  return static_cast<std::size_t>(std::max_element(lw.begin(), lw.end()) - lw.begin());
}

// Copying a particle copies its pose and one map root pointer: no landmark EKF and no trie node
// is copied (landmark_map.hpp), so resampling costs O(N), whatever the map size.
void FastSlam::resample() {
  if (particles_.empty()) return;
  const std::size_t best = best_particle();
  const std::vector<std::size_t> source = resample_sources();
  // The representative stays the highest-weight particle: its first copy, if it has one.
  const auto copy = std::find(source.begin(), source.end(), best);
  representative_ = copy == source.end() ? 0 : static_cast<std::size_t>(copy - source.begin());
}

std::vector<std::size_t> FastSlam::resample_sources() {
  const std::vector<std::size_t> source = systematic_resample(log_weights(), rng_);
  std::vector<FastSlamParticle> next;
  next.reserve(particles_.size());
  for (std::size_t i : source) next.push_back(particles_[i]);
  particles_ = std::move(next);
  const double uniform = -std::log(static_cast<double>(particles_.size()));
  for (FastSlamParticle& particle : particles_) particle.log_weight = uniform;
  ++counters_.resamplings;
  counters_.particle_copies += particles_.size();
  mean_cache_.resize(0);
  return source;
}

// Normalised in log space (particle_weights.hpp); resampled when N_eff < threshold · N. The
// representative is the highest-weight particle, or its first copy after resampling.
void FastSlam::reweight(const std::vector<double>& before) {
  std::vector<double> lw = log_weights();
  if (!normalize_log_weights(lw)) lw = before;  // every particle failed: keep the old weights
  set_log_weights(lw);
  last_update_n_eff_ = sextant::effective_sample_size(lw);
  representative_ = best_particle();
  if (last_update_n_eff_ < s_.resample_threshold * static_cast<double>(particles_.size())) resample();
}

}  // namespace sextant
