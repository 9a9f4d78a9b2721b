// PlaneSlam's steps 3–6 per particle for FastSLAM (plane_slam.hpp, plane_particle_association.hpp):
// every particle associates the scan's planes with its own landmarks, at its own pose.
#include <chrono>

#include "sextant/filters/fastslam.hpp"
#include "sextant/filters/plane_particle_association.hpp"
#include "sextant/filters/plane_slam.hpp"
#include "sextant/filters/plane_slam_model.hpp"

namespace sextant {

void PlaneSlam::particle_step(PlaneSlamStep& out) {
  auto& particles = dynamic_cast<FastSlam&>(*filter_);
  SlamStepRecord& rec = out.filter;
  const PlaneParticleAssociator associator(std::make_shared<PlaneSlamModel>(), extraction_.landmarks,
                                           s_.association, s_.observation_noise(), gate_, s_.merge_semantics);
  const ParticleAssociationStep r =
      particles.update_associating(associator.observations(), s_.observation_noise(), associator);
  out.candidates_tested = r.candidates_tested;
  out.observation_landmark = r.observation_landmark;
  out.matched = r.matched;
  out.gated = r.gated;
  out.association_seconds = associator.seconds();
  rec.update_status = r.result.status;
  rec.update_seconds = r.result.seconds - associator.seconds();
  if (r.result.ok()) {
    rec.updated = r.matched;
    rec.augmented = r.augmented;
  }
  map_ = particle_semantic_map(particles.particles().at(r.representative));
  rec.pose = filter_->pose();
  if (s_.record_pose_covariance) rec.pose_covariance = filter_->joint_covariance({});
  out.map_size = map_.size();
}

}  // namespace sextant
