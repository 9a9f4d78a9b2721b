#pragma once
// FastSLAM 2.0 (Montemerlo, Thrun, Koller and Wegbreit, IJCAI 2003) over any SlamModel — the
// plane landmarks of §4.2 (plane_slam_model.hpp) with the same vehicle model (4.72), observation
// model (4.64) and augmentation (4.57–4.58) and their Jacobians as the Gaussian filters.
//
// Rao-Blackwellised: N particles, each a pose hypothesis and, per landmark, a small EKF (mean and
// covariance of that landmark alone) in a copy-on-write LandmarkMap (landmark_map.hpp).
//   predict(u, Q):  each particle's pose becomes the Gaussian N(f(s, u), G_u Q G_uᵀ) (eq. 4.72
//                   linearised in the control), not yet sampled; a second predict without an
//                   update propagates it (F Σ Fᵀ + G_u Q G_uᵀ).
//   update(zs, R, associations):  per particle, the FastSLAM 2.0 proposal — the pose posterior
//                   after the observations of known landmarks, linearised at the predicted pose —
//                   is sampled, the observed landmarks' EKFs are updated at the sampled pose and
//                   the particle's log weight grows by the observation likelihood under the
//                   proposal's linearisation (fastslam_update.cpp). Then, if N_eff < threshold·N,
//                   systematic resampling (particle_weights.hpp).
//   augment(z, R):  per particle, a pose still pending is sampled from its Gaussian, then the new
//                   landmark m = g(s, z) with covariance G_z R G_zᵀ (eqs. 4.57–4.58, 4.67 at a
//                   known pose); weights unchanged (a first sighting says nothing about the pose).
// Association is external, as for every Filter: update() takes the landmark indices, and every
// particle uses the same ones (the plane SLAM runner associates semantically against the
// weighted-mean map, plane_slam.hpp; per-particle association is not done).
//
// The Filter view of the particle set (documented choice):
//   mean()        the weighted mean [pose; landmarks] (pose angles: circular mean; planes:
//                 weighted mean renormalised to a unit normal);
//   covariance()  the covariance of the particle mixture: Σ_i w_i (C_i + (x_i − x̄)(x_i − x̄)ᵀ)
//                 with C_i = blockdiag(pending pose covariance, landmark EKF covariances) — the
//                 particle spread of the pose and landmarks plus the EKFs' own uncertainty.
//                 Landmarks of one particle are independent given its path, so C_i is block
//                 diagonal; the cross terms come from the spread. O(N n²);
//   joint_covariance(ids)  the same, over the pose and the given landmarks only, O(N (p + k l)²).
// Costs per step (N particles, M landmarks, k observations): predict O(N); update
// O(N (k³ + k log M)) and resampling O(N) (no map is copied, landmark_map.hpp); augment
// O(N log M). The Filter views are not O(log M): mean() is O(N M) (cached until the next step),
// covariance() O(N M²) and joint_covariance(ids) O(N |ids|²) — a runner timing steps against
// the map size should not ask for covariance() (run_slam: record_pose_covariance = false).
// initialize(x0, P0): poses are drawn from N(x0_v, P0_vv); landmarks in x0 start at their
// conditional Gaussian given each particle's pose, keeping only the diagonal landmark blocks
// (FastSLAM cannot hold correlations between landmarks of one particle).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sextant/core/rng.hpp"
#include "sextant/filters/filter.hpp"
#include "sextant/filters/landmark_map.hpp"

namespace sextant {

struct FastSlamSettings {
  int particles = 50;               ///< N
  double resample_threshold = 0.5;  ///< resample when N_eff < resample_threshold · N (0: never, 1: always)
  bool valid(std::string* why) const;
};

/// One particle: a pose (sampled, or a pending Gaussian after predict), its log weight and map.
struct FastSlamParticle {
  Eigen::VectorXd pose;             ///< sampled pose, or the mean of the pending pose Gaussian
  Eigen::MatrixXd pose_covariance;  ///< pending pose covariance; zero once sampled
  bool pending = false;             ///< pose not yet sampled since the last predict
  double log_weight = 0.0;          ///< normalised over the set (Σ exp = 1)
  LandmarkMap map;
};

/// Counts over the filter's life, for the cost tests and the experiment.
struct FastSlamCounters {
  MapCounters map;                  ///< landmark EKFs written and trie nodes copied
  std::size_t resamplings = 0;      ///< steps that resampled
  std::size_t particle_copies = 0;  ///< particles copied by resampling (each a root pointer)
};

class FastSlam final : public Filter {
 public:
  /// Throws std::invalid_argument for invalid settings. `seed` seeds the filter's own Rng.
  FastSlam(std::shared_ptr<const SlamModel> model, FastSlamSettings settings = {}, std::uint64_t seed = 1);

  std::string name() const override { return "fastslam2"; }
  const SlamModel& model() const override { return *model_; }
  StepResult initialize(const Eigen::VectorXd& x0, const Eigen::MatrixXd& P0) override;
  StepResult predict(const Eigen::VectorXd& u, const Eigen::MatrixXd& Q) override;
  StepResult update(const std::vector<Eigen::VectorXd>& zs, const Eigen::MatrixXd& R,
                    const std::vector<int>& associations) override;
  StepResult augment(const Eigen::VectorXd& z, const Eigen::MatrixXd& R) override;
  Eigen::VectorXd mean() const override;
  Eigen::MatrixXd covariance() const override;
  Eigen::MatrixXd joint_covariance(const std::vector<int>& landmarks) const override;
  int num_landmarks() const override { return landmarks_; }
  std::string approximation() const override;

  const std::vector<FastSlamParticle>& particles() const { return particles_; }
  /// Normalised weights exp(log_weight_i).
  std::vector<double> weights() const;
  double effective_sample_size() const;
  /// N_eff after the last update's weighting, before its resampling (N before any update).
  double last_update_effective_sample_size() const { return last_update_n_eff_; }
  /// The particle of largest weight (first on ties).
  std::size_t best_particle() const;
  const FastSlamCounters& counters() const { return counters_; }
  /// Systematic resampling now, whatever N_eff (update() resamples by N_eff on its own).
  void resample();

 private:
  /// Proposal, landmark updates and log-weight increment of one particle (fastslam_update.cpp).
  StepStatus update_particle(FastSlamParticle& particle, const std::vector<Eigen::VectorXd>& zs,
                             const Eigen::MatrixXd& R, const std::vector<int>& associations);
  /// Draws a pending pose from its Gaussian.
  StepStatus sample_pose(FastSlamParticle& particle);
  std::vector<double> log_weights() const;
  void set_log_weights(const std::vector<double>& log_weights);
  StepResult finish(StepStatus status, double seconds);

  std::shared_ptr<const SlamModel> model_;
  FastSlamSettings s_;
  Rng rng_;
  std::vector<FastSlamParticle> particles_;
  int landmarks_ = 0;
  double last_update_n_eff_ = 0.0;
  FastSlamCounters counters_;
  mutable Eigen::VectorXd mean_cache_;  ///< mean(), cleared by every step
};

/// x ~ N(mean, covariance) through a symmetric square root (eigen-decomposition, negative
/// eigenvalues clamped to 0, so positive semi-definite covariances — a pose known exactly —
/// draw the mean). Returns false when the covariance is not finite.
bool draw_gaussian(const Eigen::VectorXd& mean, const Eigen::MatrixXd& covariance, Rng& rng,
                   Eigen::VectorXd& out);

}  // namespace sextant
