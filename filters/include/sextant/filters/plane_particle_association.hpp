#pragma once
// Per-particle semantic association of plane landmarks for FastSLAM (fastslam.hpp's
// ParticleAssociator; Montemerlo et al. 2003, §3: each particle makes its own decision). For one
// scan's extracted planes z = (nᴸ, dᴸ) (eq. 4.64), per particle:
//   1. the planes are put in the world with the particle's predicted pose (eqs. 4.57–4.61);
//   2. they are associated with the particle's own landmarks — its EKF's (n, d) with the semantic
//      data (centroid, covariance, hull, area) it keeps beside each (PlaneSemantics, the
//      landmark's LandmarkAttachment) — by the C_o, C_t, C_p tests and conflict rule of §4.2.5
//      (features/association.hpp, the same function as the Gaussian filters', candidates within
//      the search radius of the centroid);
//   3. a match whose innovation fails the χ² gate is dropped (kUnexplained), with the particle's
//      innovation S = G_s P_t G_sᵀ + G_θ Σ_θ G_θᵀ + R (particle_innovation_distance); the
//      Gaussian filters' gate (innovation_gate.hpp) with the particle's moments;
//   4. an observation without a match is a new landmark of that particle (kNewLandmark).
// After the particle's update, attach() keeps each observed landmark's semantics in step with
// it: the plane from the EKF (normal on the semantic side), the observation's semantics in the
// world of the sampled pose merged in (merge_landmark_semantics, PlaneSlam's step 6).
// p0 (unexplained_log_likelihood): the Gaussian density of an innovation on the gate's edge,
// log N = −½(γ + log|2πR|), γ the gate quantile (χ²₄ at 0.99 when the gate is off): an
// unexplained observation counts as much as a match just inside the gate with S = R.
// Cost per particle: O(k M) centroid distances and O(k c) tests (c candidates per observation),
// k + updated landmarks' hull merges.
#include <memory>
#include <vector>

#include "sextant/features/association.hpp"
#include "sextant/features/landmark.hpp"
#include "sextant/filters/fastslam.hpp"

namespace sextant {

/// A particle's semantic data of one plane landmark, in that particle's world frame; its plane is
/// the landmark EKF's mean (n, d) with the normal on the observed side.
struct PlaneSemantics final : LandmarkAttachment {
  PlaneLandmark landmark;
};

class PlaneParticleAssociator final : public ParticleAssociator {
 public:
  /// `observed`: the scan's planes in the sensor frame (their inlier indices are dropped);
  /// R: the noise of one observation; gate: χ² quantile (0: no gate).
  PlaneParticleAssociator(std::shared_ptr<const SlamModel> model, const std::vector<PlaneLandmark>& observed,
                          const AssociationSettings& settings, const Eigen::MatrixXd& R, double gate,
                          bool merge_semantics);

  /// z = (nᴸ, dᴸ) of every observed plane, in order: update_associating's zs.
  const std::vector<Eigen::VectorXd>& observations() const { return zs_; }
  ParticleDecision associate(const FastSlamParticle& particle) const override;
  double unexplained_log_likelihood() const override { return log_p0_; }
  /// Wall time spent in associate() so far [s].
  double seconds() const { return seconds_; }
  std::shared_ptr<const LandmarkAttachment> attach(const Eigen::VectorXd& pose, std::size_t observation,
                                                   const LandmarkEkf& landmark) const override;

 private:
  std::shared_ptr<const SlamModel> model_;
  std::vector<PlaneLandmark> observed_;
  std::vector<Eigen::VectorXd> zs_;
  AssociationSettings settings_;
  Eigen::MatrixXd R_;
  double gate_ = 0.0;
  bool merge_ = true;
  double log_p0_ = 0.0;
  mutable double seconds_ = 0.0;
};

/// The semantic map of one particle (PlaneSemantics per landmark; a landmark without one gets
/// its plane only).
std::vector<PlaneLandmark> particle_semantic_map(const FastSlamParticle& particle);

}  // namespace sextant
