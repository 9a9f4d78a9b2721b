#include <gtest/gtest.h>

#include <cmath>

#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"
#include "test_util.hpp"

namespace sextant {
namespace {

// eq. (3.8) written out element by element (with Ry's last row [−sβ 0 cβ]).
Eigen::Matrix3d thesis_rotation(double a, double b, double g) {
  Eigen::Matrix3d Rx, Ry, Rz;
  Rx << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
  Ry << std::cos(b), 0, std::sin(b), 0, 1, 0, -std::sin(b), 0, std::cos(b);
  Rz << std::cos(g), -std::sin(g), 0, std::sin(g), std::cos(g), 0, 0, 0, 1;
  return Rx * Ry * Rz;
}

TEST(Pose, RotationMatchesEquation38) {
  for (double a : {-2.0, -0.3, 0.0, 0.7}) {
    for (double b : {-1.2, 0.0, 0.4}) {
      for (double g : {-3.0, 0.1, 2.5}) {
        EXPECT_TRUE(rotation_from_euler(a, b, g).isApprox(thesis_rotation(a, b, g), 1e-12));
      }
    }
  }
}

TEST(Pose, MatchesThreeDtkEulerToMatrix4) {
  const Pose6 pose{1.0, -2.0, 3.0, 0.3, -0.5, 1.1};
  const Eigen::Matrix4d expected =
      test::threedtk_euler_to_matrix4({pose.x, pose.y, pose.z}, {pose.alpha, pose.beta, pose.gamma});
  EXPECT_TRUE(to_isometry(pose).matrix().isApprox(expected, 1e-12));
}

TEST(Pose, EulerRoundTrip) {
  for (double a : {-3.0, -0.3, 0.0, 1.4}) {
    for (double b : {-1.5, -0.2, 0.0, 1.1}) {
      for (double g : {-2.9, 0.0, 0.6, 3.1}) {
        const Pose6 pose{0.5, 1.5, -2.5, a, b, g};
        const Pose6 back = to_pose6(to_isometry(pose));
        EXPECT_NEAR(back.alpha, a, 1e-9);
        EXPECT_NEAR(back.beta, b, 1e-9);
        EXPECT_NEAR(back.gamma, g, 1e-9);
        EXPECT_NEAR(back.x, 0.5, 1e-12);
      }
    }
  }
}

TEST(Pose, GimbalLockKeepsTheRotation) {
  const Eigen::Matrix3d R = rotation_from_euler(0.4, M_PI / 2, 0.3);
  const Eigen::Vector3d angles = euler_from_rotation(R);
  EXPECT_TRUE(rotation_from_euler(angles[0], angles[1], angles[2]).isApprox(R, 1e-9));
}

TEST(Pose, ComposeInverseRelative) {
  const Eigen::Isometry3d a = to_isometry({1, 2, 3, 0.1, 0.2, 0.3});
  const Eigen::Isometry3d b = to_isometry({-4, 0.5, 1, -0.4, 0.1, 2.0});
  EXPECT_TRUE((compose(a, inverse(a))).matrix().isApprox(Eigen::Matrix4d::Identity(), 1e-12));
  EXPECT_TRUE(compose(a, relative(a, b)).matrix().isApprox(b.matrix(), 1e-12));
  EXPECT_NEAR(rotation_angle(relative(a, a)), 0.0, 1e-7);
  EXPECT_NEAR(translation_norm(to_isometry({3, 4, 0, 0, 0, 0})), 5.0, 1e-12);
}

TEST(Pose, WrapAngle) {
  EXPECT_NEAR(wrap_angle(3 * M_PI), M_PI, 1e-12);
  EXPECT_NEAR(wrap_angle(-M_PI), M_PI, 1e-12);
  EXPECT_NEAR(wrap_angle(2 * M_PI + 0.25), 0.25, 1e-12);
  EXPECT_NEAR(wrap_angle(-0.25), -0.25, 1e-12);
}

TEST(Pose, NonFiniteIsDetected) {
  Pose6 pose;
  EXPECT_TRUE(is_finite(pose));
  pose.beta = std::nan("");
  EXPECT_FALSE(is_finite(pose));
  EXPECT_FALSE(is_finite(to_isometry(pose)));
}

// The angle of a rotation is exact at every size: acos of the trace could not resolve angles
// below about 1.5e-8 rad (identical rotations came out 1.4e-8 rad apart), nor near π.
TEST(RotationAngle, ExactForTinyMiddleAndNearHalfTurnAngles) {
  for (const double angle : {0.0, 1e-12, 1e-9, 3e-8, 0.3, 2.0, kPi - 1e-9}) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    EXPECT_NEAR(rotation_angle(T), angle, 1e-15 + 1e-12 * angle) << angle;
  }
}

}  // namespace
}  // namespace sextant
