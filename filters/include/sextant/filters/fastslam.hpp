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
// Association, two ways:
//   external, as for every Filter: update() takes the landmark indices and every particle uses
//     the same ones (true association, run_slam; or PlaneSlam with particle_association off,
//     which associates semantically against the weighted-mean map);
//   per particle (Montemerlo et al. 2003, §3 "data association": each particle makes its own
//     decision): update_associating(zs, R, associator) asks a ParticleAssociator, per particle
//     and with that particle's predicted pose and its own landmark EKFs, which landmark each
//     observation is (or new, or unexplained); the particle is updated with its known ones,
//     augmented with its new ones at its sampled pose, and its weight is the FastSLAM 2.0 weight
//     of the known ones times p0 per unexplained or new observation (the associator's
//     unexplained_log_likelihood: Montemerlo's "likelihood of a new feature" p0). Particles'
//     maps then differ in size and in which plane an index names; new landmarks are push_backs
//     into the particle's own copy-on-write map (O(log M), no map copied). PlaneSlam does this
//     for the plane landmarks with the semantic tests of §4.2.5 and the χ² gate per particle
//     (plane_particle_association.hpp). After the first update_associating, update() and
//     augment() return kInvalidInput (an index no longer names one landmark in every particle).
//
// The Filter view of the particle set (documented choice):
//   mean()        the weighted mean [pose; landmarks] (pose angles: circular mean; planes:
//                 weighted mean renormalised to a unit normal). Per-particle association: the
//                 weighted-mean pose and the landmarks of the representative particle (the
//                 highest-weight one; after a resampling, a copy of the one that had the highest
//                 weight before it), whose map num_landmarks() counts;
//   covariance()  the covariance of the particle mixture: Σ_i w_i (C_i + (x_i − x̄)(x_i − x̄)ᵀ)
//                 with C_i = blockdiag(pending pose covariance, landmark EKF covariances) — the
//                 particle spread of the pose and landmarks plus the EKFs' own uncertainty.
//                 Landmarks of one particle are independent given its path, so C_i is block
//                 diagonal; the cross terms come from the spread. O(N n²);
//   joint_covariance(ids)  the same, over the pose and the given landmarks only, O(N (p + k l)²).
//                 Per-particle association: the pose block is the mixture's, the landmark blocks
//                 the representative's EKF covariances (no cross terms).
// Costs per step (N particles, M landmarks, k observations): predict O(N); update
// O(N (k³ + k log M)) and resampling O(N) (no map is copied, landmark_map.hpp); augment
// O(N log M); update_associating adds the associator's cost (planes: O(N k M) centroid
// distances, plane_particle_association.hpp) and O(N k log M) map writes. The Filter views are
// not O(log M): mean() is O(N M) (cached until the next step), covariance() O(N M²) and
// joint_covariance(ids) O(N |ids|²) — a runner timing steps against the map size should not ask
// for covariance() (run_slam: record_pose_covariance = false).
//
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

/// Per-particle association (update_associating): what an observation is in one particle.
inline constexpr int kNewLandmark = -1;  ///< a new landmark of this particle
inline constexpr int kUnexplained = -2;  ///< dropped (e.g. gated): no update, no landmark

/// One particle's decision: per observation a landmark of the particle's map, kNewLandmark or
/// kUnexplained.
struct ParticleDecision {
  std::vector<int> landmarks;
  std::size_t candidates_tested = 0;  ///< pairs the associator evaluated
  std::size_t gated = 0;              ///< candidate matches it dropped (among the kUnexplained)
};

/// Decides the association of one step's observations in each particle (update_associating).
/// It holds the observations itself (what it needs beyond z: planes' semantics), in the order of
/// the zs given to update_associating. Called for one particle at a time, in order.
class ParticleAssociator {
 public:
  virtual ~ParticleAssociator() = default;
  /// The decision for `particle` at its predicted pose (pose, pose_covariance pending) and map.
  virtual ParticleDecision associate(const FastSlamParticle& particle) const = 0;
  /// log p0: the likelihood credited to an observation no known landmark explains (new or
  /// unexplained), so that particles deciding differently get comparable weights.
  virtual double unexplained_log_likelihood() const = 0;
  /// The attachment of a landmark after `observation` updated (landmark.attachment: the previous
  /// one) or created it (null) at the particle's sampled `pose`; null keeps none.
  virtual std::shared_ptr<const LandmarkAttachment> attach(const Eigen::VectorXd& pose,
                                                           std::size_t observation,
                                                           const LandmarkEkf& landmark) const = 0;
};

/// What update_associating did, with the representative particle's decision.
struct ParticleAssociationStep {
  StepResult result;
  std::size_t representative = 0;                     ///< the particle reported (after the step's resampling)
  std::vector<int> observation_landmark;              ///< its landmark per observation (−1: unexplained)
  std::size_t matched = 0, augmented = 0, gated = 0;  ///< its counts
  std::size_t candidates_tested = 0;                  ///< over every particle
  double n_eff = 0.0;                                 ///< after the weighting, before resampling
};

/// νᵀ S⁻¹ ν of observation z against landmark j of one particle at its predicted pose:
/// ν = z − g(ŝ, μ_θ), S = G_s P_t G_sᵀ + G_θ Σ_θ G_θᵀ + R (the innovation of the FastSLAM 2.0
/// proposal, Montemerlo et al. 2003, §3; P_t = 0 for a sampled pose). +∞ when S is not positive
/// definite or the inputs are not finite. The per-particle χ² gate (innovation_gate.hpp's).
double particle_innovation_distance(const SlamModel& model, const FastSlamParticle& particle,
                                    const Eigen::VectorXd& z, const Eigen::MatrixXd& R, int landmark);

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
  /// Per-particle association and update (see the header comment; fastslam_associating.cpp).
  ParticleAssociationStep update_associating(const std::vector<Eigen::VectorXd>& zs, const Eigen::MatrixXd& R,
                                             const ParticleAssociator& associator);
  Eigen::VectorXd mean() const override;
  Eigen::MatrixXd covariance() const override;
  Eigen::MatrixXd joint_covariance(const std::vector<int>& landmarks) const override;
  int num_landmarks() const override;
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
  /// True once update_associating ran: the particles' maps are their own.
  bool associates_per_particle() const { return per_particle_; }
  /// The particle whose map the Filter view reports (best_particle() until per-particle association).
  std::size_t representative() const { return per_particle_ ? representative_ : best_particle(); }

 private:
  /// Proposal, landmark updates and log-weight increment of one particle (fastslam_update.cpp).
  /// `attach`, when given, sets each updated landmark's attachment (observation index in zs).
  StepStatus update_particle(FastSlamParticle& particle, const std::vector<Eigen::VectorXd>& zs,
                             const Eigen::MatrixXd& R, const std::vector<int>& associations,
                             const ParticleAssociator* attach = nullptr,
                             const std::vector<std::size_t>* observation_ids = nullptr);
  /// Draws a pending pose from its Gaussian.
  StepStatus sample_pose(FastSlamParticle& particle);
  /// One particle's decision applied: update, augmentation, attachments and p0 (fastslam_associating.cpp).
  StepStatus associate_particle(FastSlamParticle& particle, const std::vector<Eigen::VectorXd>& zs,
                                const Eigen::MatrixXd& R, const ParticleAssociator& associator,
                                const ParticleDecision& decision);
  /// Normalises the weights (`before` when every particle failed), records N_eff, picks the
  /// representative and resamples when N_eff is below the threshold.
  void reweight(const std::vector<double>& before);
  std::vector<std::size_t> resample_sources();
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
  bool per_particle_ = false;           ///< update_associating has run
  std::size_t representative_ = 0;      ///< per-particle association: the reported particle
  mutable Eigen::VectorXd mean_cache_;  ///< mean(), cleared by every step
};

/// x ~ N(mean, covariance) through a symmetric square root (eigen-decomposition, negative
/// eigenvalues clamped to 0, so positive semi-definite covariances — a pose known exactly —
/// draw the mean). Returns false when the covariance is not finite.
bool draw_gaussian(const Eigen::VectorXd& mean, const Eigen::MatrixXd& covariance, Rng& rng,
                   Eigen::VectorXd& out);

}  // namespace sextant
