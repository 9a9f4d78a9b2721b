// FastSLAM 2.0 with per-particle semantic association (fastslam.hpp, update_associating;
// plane_particle_association.hpp) against known answers on hand-made plane patches:
//   noise-free observations of well-separated walls are associated with their own landmark in
//   every particle; two particles whose poses (or maps) differ put one observation on different
//   landmarks, each its own correct one; a new wall becomes a new landmark in every particle,
//   written into its map without copying it.
#include <gtest/gtest.h>

#include <memory>

#include "sextant/core/chi_square.hpp"
#include "sextant/core/units.hpp"
#include "sextant/filters/fastslam.hpp"
#include "sextant/filters/plane_particle_association.hpp"
#include "sextant/filters/plane_slam.hpp"
#include "sextant/filters/plane_slam_model.hpp"

namespace sextant {
namespace {

/// A rectangular wall patch in the world: centre c, normal n (turned towards the origin),
/// `along` its horizontal direction; the semantics of a plane seen by 2000 points on it.
PlaneLandmark patch(const Eigen::Vector3d& c, Eigen::Vector3d n, const Eigen::Vector3d& along,
                    double width = 6.0, double height = 3.0) {
  n.normalize();
  if (n.dot(c) > 0.0) n = -n;
  const Eigen::Vector3d u = (along - along.dot(n) * n).normalized(), v = n.cross(u);
  PlaneLandmark l;
  l.plane.normal = n;
  l.plane.d = n.dot(c);
  l.centroid = c;
  l.covariance = width * width / 12.0 * u * u.transpose() + height * height / 12.0 * v * v.transpose();
  l.inlier_count = 2000;
  l.area = width * height;
  for (const auto& [a, b] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
    l.hull.push_back(c + 0.5 * a * width * u + 0.5 * b * height * v);
  return l;
}

const PlaneLandmark kWallA = patch({6, 0, 1}, {1, 0, 0}, {0, 1, 0});
const PlaneLandmark kWallB = patch({0, 7, 1}, {0, 1, 0}, {1, 0, 0});
const PlaneLandmark kWallC = patch({-8, 0, 1}, {1, 0, 0}, {0, 1, 0});
const PlaneLandmark kWallD = patch({0, -9, 1}, {0, 1, 0}, {1, 0, 0});

Eigen::VectorXd pose_of(double x, double y, double yaw) {
  return Pose6::from_vector((Vector6d() << x, y, 0.0, 0.0, 0.0, yaw).finished()).vector();
}

/// The walls seen from `pose` (sensor frame, noise free).
std::vector<PlaneLandmark> seen_from(const Eigen::VectorXd& pose, const std::vector<PlaneLandmark>& walls) {
  return transform_landmarks(walls, to_isometry(Pose6::from_vector(pose)).inverse());
}

struct Planes {
  std::shared_ptr<const SlamModel> model = std::make_shared<PlaneSlamModel>();
  PlaneSlamSettings settings;  // R, association thresholds and the 0.99 gate of PlaneSlam
  double gate = chi_square_quantile(0.99, 4);
  PlaneParticleAssociator associator(const std::vector<PlaneLandmark>& observed) const {
    return PlaneParticleAssociator(model, observed, settings.association, settings.observation_noise(), gate,
                                   true);
  }
};

Eigen::MatrixXd small_prior() {
  return Eigen::VectorXd((Eigen::VectorXd(6) << 1e-3, 1e-3, 1e-4, 1e-6, 1e-6, 1e-5).finished()).asDiagonal();
}

// Noise-free observations of three walls metres apart: after a biased odometry step (30 cm,
// 1.7°, inside Q), every particle associates each wall with the landmark it created for it, in
// whatever order the walls come.
TEST(FastSlamAssociation, NoiseFreeWellSeparatedPlanesAreTrulyAssociatedInEveryParticle) {
  const Planes s;
  FastSlam filter(s.model, {20, 0.5}, 7);
  const Eigen::VectorXd start = pose_of(0, 0, 0), next = pose_of(2.0, 0.5, 0.1);
  ASSERT_TRUE(filter.initialize(start, small_prior()).ok());
  const auto first = s.associator(seen_from(start, {kWallA, kWallB, kWallC}));
  const ParticleAssociationStep r0 =
      filter.update_associating(first.observations(), s.settings.observation_noise(), first);
  ASSERT_TRUE(r0.result.ok());
  EXPECT_EQ(r0.augmented, 3u);
  Vector6d u = odometry_increment(Pose6::from_vector(start), Pose6::from_vector(next));
  u[0] += 0.3;
  u[5] += 0.03;
  ASSERT_TRUE(filter.predict(u, s.settings.process_noise()).ok());
  const auto second = s.associator(seen_from(next, {kWallC, kWallA, kWallB}));  // another order
  for (const FastSlamParticle& particle : filter.particles()) {
    const ParticleDecision d = second.associate(particle);
    EXPECT_EQ(d.landmarks, (std::vector<int>{2, 0, 1}));
    EXPECT_EQ(d.gated, 0u);
  }
  const ParticleAssociationStep r1 =
      filter.update_associating(second.observations(), s.settings.observation_noise(), second);
  ASSERT_TRUE(r1.result.ok());
  EXPECT_EQ(r1.matched, 3u);
  EXPECT_EQ(r1.observation_landmark, (std::vector<int>{2, 0, 1}));
  for (const FastSlamParticle& particle : filter.particles()) EXPECT_EQ(particle.map.size(), 3);
  EXPECT_EQ(filter.num_landmarks(), 3);
}

/// A particle at `pose` (sampled) whose map holds `walls` (world frame) as landmarks 0, 1, ….
FastSlamParticle particle_with(const Eigen::VectorXd& pose, const std::vector<PlaneLandmark>& walls) {
  FastSlamParticle p;
  p.pose = pose;
  p.pose_covariance = Eigen::MatrixXd::Zero(6, 6);
  for (const PlaneLandmark& w : walls) {
    auto semantics = std::make_shared<PlaneSemantics>();
    semantics->landmark = w;
    p.map.push_back(LandmarkEkf{plane_vector(w.plane), 1e-4 * Eigen::MatrixXd::Identity(4, 4), semantics});
  }
  return p;
}

// Two parallel walls 3 m apart (x = 5 and x = 8). An observation of a wall 5 m ahead is the
// first wall for a particle at the origin and the second for a particle 3 m further on; and with
// one pose, it is whichever landmark index the particle's own map gave the wall at x = 5.
TEST(FastSlamAssociation, EachParticleAssociatesWithItsOwnPoseAndMap) {
  const Planes s;
  const PlaneLandmark near = patch({5, 0, 1}, {1, 0, 0}, {0, 1, 0});
  const PlaneLandmark far = patch({8, 0, 1}, {1, 0, 0}, {0, 1, 0});
  const auto associator = s.associator(seen_from(pose_of(0, 0, 0), {near}));
  const FastSlamParticle at_origin = particle_with(pose_of(0, 0, 0), {near, far});
  const FastSlamParticle ahead = particle_with(pose_of(3, 0, 0), {near, far});
  EXPECT_EQ(associator.associate(at_origin).landmarks, std::vector<int>{0});
  EXPECT_EQ(associator.associate(ahead).landmarks, std::vector<int>{1});
  const FastSlamParticle reversed = particle_with(pose_of(0, 0, 0), {far, near});
  EXPECT_EQ(associator.associate(reversed).landmarks, std::vector<int>{1});
  // Ahead by 1.5 m the wall lands between them, 1.5 m from each: nothing passes C_t (1 m).
  const FastSlamParticle between = particle_with(pose_of(1.5, 0, 0), {near, far});
  EXPECT_EQ(associator.associate(between).landmarks, std::vector<int>{kNewLandmark});
}

// The χ² gate per particle: a particle turned by 5° sees the wall's normal 5° off its landmark's.
// That passes the semantic tests (C_o < 20°, the centroids nearly coincide) but with the pose and
// landmark known (S ≈ R, σ_n = 0.02) ν'S⁻¹ν ≈ (0.087 / 0.02)² ≈ 19 > χ²₄(0.99) = 13.3: dropped.
TEST(FastSlamAssociation, MatchOutsideTheParticlesGateIsDropped) {
  const Planes s;
  const PlaneLandmark wall = patch({5, 0, 1}, {1, 0, 0}, {0, 1, 0});
  const auto associator = s.associator(seen_from(pose_of(0, 0, 0), {wall}));
  const ParticleDecision turned =
      associator.associate(particle_with(pose_of(0, 0, 5.0 * kPi / 180.0), {wall}));
  EXPECT_EQ(turned.landmarks, std::vector<int>{kUnexplained});
  EXPECT_EQ(turned.gated, 1u);
  // Turned by 1°: ν'S⁻¹ν ≈ 0.8, kept.
  const ParticleDecision slightly =
      associator.associate(particle_with(pose_of(0, 0, 1.0 * kPi / 180.0), {wall}));
  EXPECT_EQ(slightly.landmarks, std::vector<int>{0});
}

// A wall first seen in the second scan becomes landmark 2 of every particle, at the truth
// (noise-free, the pose near the truth); the two known walls are updated. Per particle exactly
// three landmark EKFs are written (two updates, one new): no map is copied.
TEST(FastSlamAssociation, ANewPlaneCreatesALandmarkInEveryParticle) {
  const Planes s;
  const int n = 10;
  FastSlam filter(s.model, {n, 0.0}, 3);  // never resample: the particles stay apart
  const Eigen::VectorXd start = pose_of(0, 0, 0), next = pose_of(1.0, 0.0, 0.05);
  ASSERT_TRUE(filter.initialize(start, small_prior()).ok());
  const auto first = s.associator(seen_from(start, {kWallA, kWallB}));
  ASSERT_TRUE(
      filter.update_associating(first.observations(), s.settings.observation_noise(), first).result.ok());
  ASSERT_TRUE(filter
                  .predict(odometry_increment(Pose6::from_vector(start), Pose6::from_vector(next)),
                           s.settings.process_noise())
                  .ok());
  const std::size_t written = filter.counters().map.landmarks_written;
  const auto second = s.associator(seen_from(next, {kWallA, kWallB, kWallD}));
  const ParticleAssociationStep r =
      filter.update_associating(second.observations(), s.settings.observation_noise(), second);
  ASSERT_TRUE(r.result.ok());
  EXPECT_EQ(r.matched, 2u);
  EXPECT_EQ(r.augmented, 1u);
  EXPECT_EQ(r.observation_landmark, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(filter.counters().map.landmarks_written - written, static_cast<std::size_t>(3 * n));
  // Landmark 2 of each particle is g(s, z) at that particle's own sampled pose (eqs. 4.57–4.58),
  // its semantics the observation put in the world by that pose; near the truth, as the poses are.
  const Eigen::Vector4d truth = plane_vector(kWallD.plane);
  const Eigen::VectorXd& zD = second.observations()[2];
  for (const FastSlamParticle& particle : filter.particles()) {
    ASSERT_EQ(particle.map.size(), 3);
    const LandmarkEkf& added = particle.map.get(2);
    Eigen::VectorXd expected = s.model->augment(particle.pose, zD);
    s.model->normalize_landmark(expected);
    EXPECT_LT((added.mean - expected).norm(), 1e-12);
    Eigen::Vector4d m = added.mean;
    if (m.head<3>().dot(truth.head<3>()) < 0) m = -m;
    EXPECT_LT((m - truth).norm(), 0.5);
    const auto* semantics = dynamic_cast<const PlaneSemantics*>(added.attachment.get());
    ASSERT_NE(semantics, nullptr);
    const Eigen::Vector3d centroid =
        to_isometry(Pose6::from_vector(particle.pose)) * seen_from(next, {kWallD})[0].centroid;
    EXPECT_LT((semantics->landmark.centroid - centroid).norm(), 1e-9);
  }
  EXPECT_EQ(filter.num_landmarks(), 3);
  EXPECT_EQ(filter.mean().size(), 6 + 3 * 4);
  EXPECT_TRUE(filter.joint_covariance({2}).allFinite());
  // Indices no longer name one landmark in every particle: the external update is refused.
  EXPECT_EQ(filter.update({second.observations()[0]}, s.settings.observation_noise(), {0}).status,
            StepStatus::kInvalidInput);
}

}  // namespace
}  // namespace sextant
