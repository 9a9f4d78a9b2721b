// evaluate_trajectory and the pose association behind `sextant eval`, with known answers: a copy
// of the reference moved rigidly (ATE 0 after se3 and origin, the offset without alignment),
// scaled (0 only after sim3), and stamps that pair, collide or miss.
#include <gtest/gtest.h>

#include <cmath>

#include "sextant/core/pose.hpp"
#include "sextant/eval/trajectory_evaluation.hpp"

namespace sextant {
namespace {

/// A 40-pose figure with turns and some height: not collinear, so every alignment is unique.
Trajectory reference_loop() {
  Trajectory t;
  for (int i = 0; i < 40; ++i) {
    const double a = 0.15 * i;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(a + 0.5 * std::sin(a), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T.translation() = Eigen::Vector3d(20 * std::cos(a), 12 * std::sin(2 * a), 0.5 * std::sin(a));
    t.push_back({0.1 * i, T});
  }
  return t;
}

Trajectory moved(const Trajectory& t, const Eigen::Isometry3d& M, double scale = 1.0) {
  Trajectory out = t;
  for (StampedPose& p : out) {
    p.pose.translation() *= scale;
    p.pose = M * p.pose;
  }
  return out;
}

Eigen::Isometry3d offset() {
  Eigen::Isometry3d M = Eigen::Isometry3d::Identity();
  M.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.2, 0.1, 1).normalized()).toRotationMatrix();
  M.translation() = Eigen::Vector3d(3, -4, 0);  // |t| = 5
  return M;
}

TEST(TrajectoryEvaluation, RigidCopyIsExactAfterSe3AndOriginAndOffByTheMoveWithout) {
  const Trajectory ref = reference_loop();
  const AssociatedPoses pairs = associate_by_index(moved(ref, offset()), ref);
  ASSERT_TRUE(pairs.status.ok);
  for (Alignment a : {Alignment::se3, Alignment::sim3, Alignment::origin}) {
    TrajectoryEvaluationSettings s;
    s.alignment = a;
    const TrajectoryEvaluation e = evaluate_trajectory(pairs.estimate, pairs.reference, s);
    ASSERT_TRUE(e.status.ok) << e.status.message;
    EXPECT_NEAR(e.ate.translation.rms, 0.0, 1e-9) << to_string(a);
    EXPECT_NEAR(e.ate.rotation.rms, 0.0, 1e-7) << to_string(a);  // an angle from acos: √ε
    EXPECT_NEAR(e.wulf.position_rms, 0.0, 1e-9) << to_string(a);
    EXPECT_NEAR(e.rpe.translation.rms, 0.0, 1e-9);
    EXPECT_NEAR(e.kummerle.translation_rms, 0.0, 1e-9);
  }
  TrajectoryEvaluationSettings none;
  none.alignment = Alignment::none;
  const TrajectoryEvaluation e = evaluate_trajectory(pairs.estimate, pairs.reference, none);
  EXPECT_NEAR(e.ate.rotation.rms, 0.4, 1e-9);  // the move's rotation, at every pose
  double squares = 0.0;                        // ‖M·p − p‖ at every pose, by hand
  for (const StampedPose& p : ref)
    squares += (offset() * p.pose.translation() - p.pose.translation()).squaredNorm();
  EXPECT_NEAR(e.ate.translation.rms, std::sqrt(squares / static_cast<double>(ref.size())), 1e-9);
  EXPECT_NEAR(e.rpe.translation.rms, 0.0, 1e-9) << "relative metrics ignore a rigid move";
  // Translation only: the ATE without alignment is exactly the offset.
  Eigen::Isometry3d shift = Eigen::Isometry3d::Identity();
  shift.translation() = Eigen::Vector3d(3, -4, 0);
  const AssociatedPoses shifted = associate_by_index(moved(ref, shift), ref);
  EXPECT_NEAR(evaluate_trajectory(shifted.estimate, shifted.reference, none).ate.translation.rms, 5.0, 1e-9);
}

TEST(TrajectoryEvaluation, ScaledCopyIsExactOnlyAfterSim3) {
  const Trajectory ref = reference_loop();
  const AssociatedPoses pairs = associate_by_index(moved(ref, offset(), 0.5), ref);
  TrajectoryEvaluationSettings s;
  s.alignment = Alignment::sim3;
  const TrajectoryEvaluation sim3 = evaluate_trajectory(pairs.estimate, pairs.reference, s);
  EXPECT_NEAR(sim3.ate.alignment.scale, 2.0, 1e-9);
  EXPECT_NEAR(sim3.ate.translation.rms, 0.0, 1e-9);
  EXPECT_NEAR(sim3.rpe.translation.rms, 0.0, 1e-9) << "the scaled estimate's motions match";
  s.alignment = Alignment::se3;
  EXPECT_GT(evaluate_trajectory(pairs.estimate, pairs.reference, s).ate.translation.rms, 1.0);
}

TEST(TrajectoryEvaluation, NonFinitePosesAreAnErrorNotAZero) {
  const Trajectory ref = reference_loop();
  AssociatedPoses pairs = associate_by_index(ref, ref);
  pairs.estimate[3].translation().x() = NAN;
  const TrajectoryEvaluation e = evaluate_trajectory(pairs.estimate, pairs.reference);
  EXPECT_FALSE(e.status.ok);
  EXPECT_NE(e.status.message.find("non-finite"), std::string::npos) << e.status.message;
}

TEST(PoseAssociation, PairsByNearestStampOnceAndCountsTheRest) {
  const Trajectory ref = reference_loop();  // stamps 0, 0.1, …, 3.9
  Trajectory est;
  for (std::size_t i = 0; i < ref.size(); i += 2) est.push_back({ref[i].stamp + 0.004, ref[i].pose});
  est.push_back({ref[10].stamp - 0.001, ref[10].pose});  // a rival for stamp 1.0, nearer: it wins
  est.push_back({100.0, ref[0].pose});                   // nothing near
  const AssociatedPoses p = associate_by_stamp(est, ref, 0.01);
  ASSERT_TRUE(p.status.ok);
  EXPECT_EQ(p.estimate.size(), 20u);
  EXPECT_EQ(p.unmatched_estimate, 2u);  // the farther of the two at 1.0, and the one at 100 s
  EXPECT_EQ(p.unmatched_reference, 20u);
  EXPECT_NEAR(p.largest_difference, 0.004, 1e-12);
  for (std::size_t k = 0; k < p.estimate.size(); ++k)
    EXPECT_TRUE(p.estimate[k].isApprox(p.reference[k])) << k;
  EXPECT_FALSE(associate_by_stamp(est, ref, 0.001).estimate.size() > 1);
  const AssociatedPoses none = associate_by_stamp({{50.0, ref[0].pose}}, ref, 0.01);
  EXPECT_FALSE(none.status.ok);
  EXPECT_FALSE(associate_by_index(est, ref).status.ok);
  EXPECT_NE(associate_by_index(est, ref).status.message.find("22 poses and the reference 40"),
            std::string::npos);
}

}  // namespace
}  // namespace sextant
