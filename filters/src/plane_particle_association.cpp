#include "sextant/filters/plane_particle_association.hpp"

#include <Eigen/Cholesky>

#include <chrono>
#include <cmath>

#include "sextant/core/chi_square.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"
#include "sextant/features/merging.hpp"
#include "sextant/filters/plane_slam_model.hpp"

namespace sextant {
namespace plane_particle_association {

constexpr double kLog2Pi = 1.8378770664093454836;

const PlaneLandmark* semantics_of(const LandmarkEkf& ekf) {
  const auto* s = dynamic_cast<const PlaneSemantics*>(ekf.attachment.get());
  return s ? &s->landmark : nullptr;
}

/// The EKF's plane (n, d) with the normal on `side`'s side.
Plane plane_on_side(const Eigen::VectorXd& mean, const Eigen::Vector3d& side) {
  Eigen::Vector4d v = mean.head<4>();
  if (v.head<3>().dot(side) < 0.0) v = -v;
  return plane_from_vector(v);
}

Eigen::Isometry3d pose_isometry(const Eigen::VectorXd& pose) {
  return to_isometry(Pose6::from_vector(pose.head<6>()));
}

}  // namespace plane_particle_association

PlaneParticleAssociator::PlaneParticleAssociator(std::shared_ptr<const SlamModel> model,
                                                 const std::vector<PlaneLandmark>& observed,
                                                 const AssociationSettings& settings,
                                                 const Eigen::MatrixXd& R, double gate, bool merge_semantics)
    : model_(std::move(model)),
      observed_(observed),
      settings_(settings),
      R_(R),
      gate_(gate),
      merge_(merge_semantics) {
  using namespace plane_particle_association;
  for (PlaneLandmark& o : observed_) {
    o.inliers.clear();
    zs_.emplace_back(plane_vector(o.plane));
  }
  const int od = model_->observation_dim();
  const double gamma = gate_ > 0.0 ? gate_ : chi_square_quantile(0.99, od);
  const double log_det = (2.0 * kPi * R_).ldlt().vectorD().array().log().sum();
  log_p0_ = -0.5 * (gamma + log_det);
}

// Steps 1–4 of the header: world frame at the predicted pose, §4.2.5's tests against the
// particle's own landmarks, the particle's χ² gate, new landmarks for the rest.
ParticleDecision PlaneParticleAssociator::associate(const FastSlamParticle& particle) const {
  using namespace plane_particle_association;
  const auto t0 = std::chrono::steady_clock::now();
  ParticleDecision out;
  out.landmarks.assign(observed_.size(), kNewLandmark);
  const std::vector<PlaneLandmark> world = transform_landmarks(observed_, pose_isometry(particle.pose));
  const std::size_t count = static_cast<std::size_t>(particle.map.size());
  std::vector<const PlaneLandmark*> map(count, nullptr);
  for (std::size_t j = 0; j < count; ++j) map[j] = semantics_of(particle.map.get(static_cast<int>(j)));
  const double r2 = settings_.search_radius * settings_.search_radius;
  const AssociationResult result = associate_landmarks(
      world, count, [&](std::size_t j) -> const PlaneLandmark& { return *map[j]; },
      [&](const PlaneLandmark& o, std::vector<std::size_t>* candidates) {
        candidates->clear();
        for (std::size_t j = 0; j < count; ++j)
          if (map[j] && (map[j]->centroid - o.centroid).squaredNorm() <= r2) candidates->push_back(j);
      },
      settings_);
  out.candidates_tested = result.candidates_tested;
  for (const LandmarkMatch& m : result.matches) {
    const int j = static_cast<int>(m.map);
    if (gate_ > 0.0 && !(particle_innovation_distance(*model_, particle, zs_[m.observed], R_, j) <= gate_)) {
      out.landmarks[m.observed] = kUnexplained;
      ++out.gated;
      continue;
    }
    out.landmarks[m.observed] = j;
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

// PlaneSlam's step 6 in the particle: the plane from the updated EKF, the semantics of the
// observation at the sampled pose merged in (a new landmark takes them as they are).
std::shared_ptr<const LandmarkAttachment> PlaneParticleAssociator::attach(const Eigen::VectorXd& pose,
                                                                          std::size_t observation,
                                                                          const LandmarkEkf& landmark) const {
  using namespace plane_particle_association;
  auto out = std::make_shared<PlaneSemantics>();
  const PlaneLandmark in_world = observed_.at(observation).transformed(pose_isometry(pose));
  const PlaneLandmark* previous = semantics_of(landmark);
  if (!previous) {
    out->landmark = in_world;
    out->landmark.plane = plane_on_side(landmark.mean, in_world.plane.normal);
    return out;
  }
  out->landmark = *previous;
  out->landmark.plane = plane_on_side(landmark.mean, previous->plane.normal);
  if (merge_) out->landmark = merge_landmark_semantics(out->landmark, in_world);
  return out;
}

std::vector<PlaneLandmark> particle_semantic_map(const FastSlamParticle& particle) {
  using namespace plane_particle_association;
  std::vector<PlaneLandmark> map(static_cast<std::size_t>(particle.map.size()));
  for (int j = 0; j < particle.map.size(); ++j) {
    const LandmarkEkf& ekf = particle.map.get(j);
    const PlaneLandmark* s = semantics_of(ekf);
    if (s) map[static_cast<std::size_t>(j)] = *s;
    const Eigen::Vector3d side = s ? s->plane.normal : Eigen::Vector3d(ekf.mean.head<3>());
    map[static_cast<std::size_t>(j)].plane = plane_on_side(ekf.mean, side);
  }
  return map;
}

}  // namespace sextant
