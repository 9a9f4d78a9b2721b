// The Filter's Gaussian view of the FastSLAM particle set (fastslam.hpp): the weighted mean and
// the covariance of the particle mixture, Σ_i w_i (C_i + (x_i − x̄)(x_i − x̄)ᵀ) with C_i the
// particle's block-diagonal pending-pose and landmark-EKF covariances (the law of total
// covariance over the mixture).
#include <cmath>
#include <stdexcept>

#include "sextant/filters/fastslam.hpp"

namespace sextant {
namespace fastslam_moments {

/// The particle's [pose; landmarks[0]; …] (all landmarks when `landmarks` is null).
Eigen::VectorXd particle_state(const SlamModel& model, const FastSlamParticle& particle,
                               const std::vector<int>& landmarks) {
  const int p = model.pose_dim(), l = model.landmark_dim();
  Eigen::VectorXd x(p + l * static_cast<Eigen::Index>(landmarks.size()));
  x.head(p) = particle.pose;
  for (std::size_t k = 0; k < landmarks.size(); ++k)
    x.segment(p + l * static_cast<Eigen::Index>(k), l) = particle.map.get(landmarks[k]).mean;
  return x;
}

std::vector<int> all_landmarks(int count) {
  std::vector<int> ids(static_cast<std::size_t>(count));
  for (int j = 0; j < count; ++j) ids[static_cast<std::size_t>(j)] = j;
  return ids;
}

/// Weighted mean of the particle states over `landmarks`: circular mean of the pose angles,
/// landmarks renormalised (planes: unit normal).
Eigen::VectorXd weighted_mean(const SlamModel& model, const std::vector<FastSlamParticle>& particles,
                              const std::vector<int>& landmarks) {
  const int p = model.pose_dim(), l = model.landmark_dim();
  Eigen::VectorXd x;
  std::vector<double> sin_sum(static_cast<std::size_t>(p), 0.0), cos_sum(static_cast<std::size_t>(p), 0.0);
  for (const FastSlamParticle& particle : particles) {
    const double w = std::exp(particle.log_weight);
    const Eigen::VectorXd xi = particle_state(model, particle, landmarks);
    if (x.size() == 0) x = Eigen::VectorXd::Zero(xi.size());
    x += w * xi;
    for (int a : model.pose_angles()) {
      sin_sum[static_cast<std::size_t>(a)] += w * std::sin(xi[a]);
      cos_sum[static_cast<std::size_t>(a)] += w * std::cos(xi[a]);
    }
  }
  for (int a : model.pose_angles())
    x[a] = std::atan2(sin_sum[static_cast<std::size_t>(a)], cos_sum[static_cast<std::size_t>(a)]);
  for (std::size_t k = 0; k < landmarks.size(); ++k)
    model.normalize_landmark(x.segment(p + l * static_cast<Eigen::Index>(k), l));
  return x;
}

/// Σ_i w_i (C_i + (x_i − x̄)(x_i − x̄)ᵀ) over [pose; landmarks…].
Eigen::MatrixXd mixture_covariance(const SlamModel& model, const std::vector<FastSlamParticle>& particles,
                                   const std::vector<int>& landmarks, const Eigen::VectorXd& mean) {
  const int p = model.pose_dim(), l = model.landmark_dim();
  const Eigen::Index n = mean.size();
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, n);
  for (const FastSlamParticle& particle : particles) {
    const double w = std::exp(particle.log_weight);
    if (w == 0.0) continue;
    const Eigen::VectorXd d = state_difference(model, particle_state(model, particle, landmarks), mean);
    C.selfadjointView<Eigen::Lower>().rankUpdate(d, w);
    C.topLeftCorner(p, p) += w * particle.pose_covariance;
    for (std::size_t k = 0; k < landmarks.size(); ++k)
      C.block(p + l * static_cast<Eigen::Index>(k), p + l * static_cast<Eigen::Index>(k), l, l) +=
          w * particle.map.get(landmarks[k]).covariance;
  }
  return C.selfadjointView<Eigen::Lower>();  // rankUpdate filled the lower triangle only
}

/// Per-particle association: [weighted-mean pose; the representative's landmarks] and, with
/// `covariance`, the pose block of the mixture beside the representative's landmark EKF
/// covariances (no cross terms: its landmarks are independent given its path).
Eigen::VectorXd representative_view(const SlamModel& model, const std::vector<FastSlamParticle>& particles,
                                    const FastSlamParticle& representative, const std::vector<int>& landmarks,
                                    Eigen::MatrixXd* covariance) {
  const int p = model.pose_dim(), l = model.landmark_dim();
  const Eigen::VectorXd pose = weighted_mean(model, particles, {});
  Eigen::VectorXd x = particle_state(model, representative, landmarks);
  x.head(p) = pose;
  if (covariance) {
    *covariance = Eigen::MatrixXd::Zero(x.size(), x.size());
    covariance->topLeftCorner(p, p) = mixture_covariance(model, particles, {}, pose);
    for (std::size_t k = 0; k < landmarks.size(); ++k)
      covariance->block(p + l * static_cast<Eigen::Index>(k), p + l * static_cast<Eigen::Index>(k), l, l) =
          representative.map.get(landmarks[k]).covariance;
  }
  return x;
}

}  // namespace fastslam_moments

Eigen::VectorXd FastSlam::mean() const {
  using namespace fastslam_moments;
  if (particles_.empty()) return Eigen::VectorXd();
  if (mean_cache_.size() == 0)
    mean_cache_ = per_particle_ ? representative_view(*model_, particles_, particles_[representative_],
                                                      all_landmarks(num_landmarks()), nullptr)
                                : weighted_mean(*model_, particles_, all_landmarks(landmarks_));
  return mean_cache_;
}

Eigen::MatrixXd FastSlam::covariance() const {
  using namespace fastslam_moments;
  if (particles_.empty()) return Eigen::MatrixXd();
  if (per_particle_) return joint_covariance(all_landmarks(num_landmarks()));
  return mixture_covariance(*model_, particles_, all_landmarks(landmarks_), mean());
}

Eigen::MatrixXd FastSlam::joint_covariance(const std::vector<int>& landmarks) const {
  using namespace fastslam_moments;
  for (int j : landmarks)
    if (j < 0 || j >= num_landmarks())
      throw std::out_of_range("joint_covariance: no landmark " + std::to_string(j));
  if (particles_.empty()) return Eigen::MatrixXd();
  if (per_particle_) {
    Eigen::MatrixXd C;
    representative_view(*model_, particles_, particles_[representative_], landmarks, &C);
    return C;
  }
  return mixture_covariance(*model_, particles_, landmarks, weighted_mean(*model_, particles_, landmarks));
}

}  // namespace sextant
