// A trajectory on the ground plane: a pose keeps its x, y and heading exactly; an estimate that errs
// only in height and pitch has no drift there, and one that errs over the ground keeps its drift.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sextant/eval/ground_plane.hpp"
#include "sextant/eval/trajectory_metrics.hpp"

namespace sextant {
namespace {

Eigen::Isometry3d pose(double x, double y, double z, double roll, double pitch, double yaw) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  T.linear() =
      (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  return T;
}

TEST(GroundPlane, KeepsXYAndHeadingAndDropsHeightRollAndPitch) {
  const Eigen::Isometry3d flat = on_ground_plane(pose(4.0, -2.5, 3.0, 0.2, -0.1, 0.7));
  EXPECT_TRUE(flat.isApprox(pose(4.0, -2.5, 0.0, 0.0, 0.0, 0.7), 1e-15)) << flat.matrix();
  // An x axis straight up has no heading: the yaw of 0.
  EXPECT_TRUE(on_ground_plane(pose(1.0, 2.0, 3.0, 0.0, -M_PI / 2, 0.0))
                  .isApprox(pose(1.0, 2.0, 0.0, 0, 0, 0), 1e-15));
}

/// A drive of 300 m in 1 m steps along a slow left curve.
std::vector<Eigen::Isometry3d> drive(double pitch_per_step, double lateral_per_step) {
  std::vector<Eigen::Isometry3d> poses{Eigen::Isometry3d::Identity()};
  for (int k = 0; k < 300; ++k)
    poses.push_back(poses.back() * pose(1.0, lateral_per_step, 0.0, 0.0, pitch_per_step, 0.002));
  return poses;
}

TEST(GroundPlane, AnEstimateThatErrsOnlyInPitchHasNoDriftOnTheGroundPlane) {
  const std::vector<Eigen::Isometry3d> reference = drive(0.0, 0.0);
  const std::vector<Eigen::Isometry3d> climbing = drive(0.0002, 0.0);  // pitches up 0.0115° a step
  const KittiDriftResult in_3d = kitti_drift(climbing, reference);
  ASSERT_TRUE(in_3d.status.ok) << in_3d.status.message;
  EXPECT_GT(in_3d.translation, 0.005);
  // On the ground plane only the climb's cosine shortens the motion: 1 − cos 0.06 < 0.2 % at the end.
  const KittiDriftResult flat = kitti_drift(on_ground_plane(climbing), on_ground_plane(reference));
  EXPECT_LT(flat.translation, 0.1 * in_3d.translation);

  const std::vector<Eigen::Isometry3d> sliding = drive(0.0, 0.01);  // 1 cm sideways a metre
  const KittiDriftResult sideways = kitti_drift(on_ground_plane(sliding), on_ground_plane(reference));
  EXPECT_NEAR(sideways.translation, kitti_drift(sliding, reference).translation, 1e-12);
  EXPECT_GT(sideways.translation, 0.005);
}

// An estimate right in 3D but in a world frame pitched 8° (a lidar-inertial odometry's drift before the
// stretch): aligned first, it has no drift on the ground plane, and the alignment reported is the one
// applied in 3D, which undoes the tilt; projected in its own frame it would be 1 − cos 8° ≈ 1 % short.
TEST(GroundPlane, TheEstimateIsAlignedBeforeItIsProjected) {
  const std::vector<Eigen::Isometry3d> reference = drive(0.0, 0.0);
  const Eigen::Isometry3d tilt = pose(5.0, -3.0, 40.0, 0.0, 8.0 * M_PI / 180.0, 0.0);
  std::vector<Eigen::Isometry3d> tilted;
  for (const Eigen::Isometry3d& T : reference) tilted.push_back(tilt * T);
  TrajectoryEvaluationSettings settings;
  const TrajectoryEvaluation aligned = evaluate_on_ground_plane(tilted, reference, settings);
  ASSERT_TRUE(aligned.status.ok) << aligned.status.message;
  EXPECT_LT(aligned.drift.translation, 1e-9);
  EXPECT_LT(aligned.ate.translation.rms, 1e-9);
  EXPECT_TRUE(aligned.ate.alignment.rotation.isApprox(tilt.linear().transpose(), 1e-9))
      << aligned.ate.alignment.rotation;
  EXPECT_NEAR(aligned.ate.alignment.translation.norm(), tilt.translation().norm(), 1e-6);
  settings.alignment = Alignment::none;
  const TrajectoryEvaluation own_frames = evaluate_on_ground_plane(tilted, reference, settings);
  ASSERT_TRUE(own_frames.status.ok) << own_frames.status.message;
  EXPECT_NEAR(own_frames.drift.translation, 1.0 - std::cos(8.0 * M_PI / 180.0), 2e-3);
}

}  // namespace
}  // namespace sextant
