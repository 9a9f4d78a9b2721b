// register_pair about the reference when the clouds lie far from their coordinates' origin
// (register_pair.hpp): the Velodyne pair moved 300 m and 2.2 km away registers as it does at home,
// where turning about the far origin left it metres off (2.6 m at 300 m, flagged degenerate).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/matchers/register_pair.hpp"

namespace sextant {
namespace {

const std::string kDir = std::string(SEXTANT_DATA_DIR) + "/velodyne_pair/";

Eigen::Isometry3d read_truth() {
  std::ifstream in(kDir + "fast_gicp_relative.txt");
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) in >> T.matrix()(r, c);
  return T;
}

/// Points on the faces of the box [low, high].
PointCloud box_cloud(const Eigen::Vector3f& low, const Eigen::Vector3f& high) {
  PointCloud cloud;
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j) {
      const Eigen::Vector3f t(i / 10.0f, j / 10.0f, 0.0f);
      cloud.push_back(low + (high - low).cwiseProduct(t));
      cloud.push_back(low + (high - low).cwiseProduct(Eigen::Vector3f(t.x(), 1.0f, t.y())));
    }
  return cloud;
}

TEST(RegistrationCentre, IsTheOriginWhereASensorCouldStand) {
  // All around the sensor, and only in front of it (the origin 1 m from the box): the origin.
  EXPECT_TRUE(registration_centre(box_cloud({-40, -30, -2}, {50, 35, 8})).isZero());
  EXPECT_TRUE(registration_centre(box_cloud({1, -30, -2}, {60, 30, 5})).isZero());
  // A 300 m map 130 m from the origin (MulRan keyframes in their map frame, moved 300 m): no sensor
  // stands there; with half the diagonal as the margin it counted as one.
  EXPECT_TRUE(
      registration_centre(box_cloud({130, -100, -10}, {430, 100, 20})).isApprox(Eigen::Vector3d(280, 0, 5)));
  // 300 m away from a 40 m box: its middle.
  const Eigen::Vector3d centre = registration_centre(box_cloud({-20, 280, -2}, {20, 320, 6}));
  EXPECT_TRUE(centre.isApprox(Eigen::Vector3d(0, 300, 2))) << centre.transpose();
  EXPECT_TRUE(registration_centre(PointCloud{}).isZero());
}

TEST(RegisterPair, CloudsFarFromTheirOriginRegisterAboutTheReference) {
  const Eigen::Isometry3d truth = read_truth();
  const PointCloud ref = read_cloud(kDir + "fast_gicp_251370668.pcd");
  const PointCloud in = read_cloud(kDir + "fast_gicp_251371071.pcd");
  for (const Eigen::Vector3d& offset : {Eigen::Vector3d(0, 300, 0), Eigen::Vector3d(2000, 1000, 10)}) {
    const Eigen::Isometry3d away(Eigen::Translation3d{offset});
    const PointCloud far_ref = ref.transformed(away), far_in = in.transformed(away);
    PairRegistrationRequest request;
    for (const bool with_guess : {false, true}) {
      if (with_guess) request.init = away * truth * away.inverse();
      const PairRegistration r = register_pair(far_ref, far_in, request);
      EXPECT_GT((r.centre - offset).norm(), 0.0);
      EXPECT_LT((r.centre - offset).norm(), 60.0) << r.centre.transpose();  // the middle of the box
      // Back at home: p_ref = away⁻¹ · T · away · p_in.
      const Eigen::Isometry3d home = away.inverse() * r.match.result.T * away;
      EXPECT_TRUE(r.match.result.quality.trusted())
          << offset.transpose() << " " << r.match.result.quality.reason;
      EXPECT_LT(translation_norm(relative(truth, home)), 0.05)
          << offset.transpose() << " guess " << with_guess;
      EXPECT_LT(rotation_angle(relative(truth, home)), 0.7 * M_PI / 180.0) << offset.transpose();
    }
  }
}

// A score quadratic in the centred frame's pose, S(ξ) = ½ (ξ_local(ξ) − ξ₀)ᵀ A (ξ_local(ξ) − ξ₀): its
// Hessian over ξ at the minimum, by central differences, is hessian_in_coordinates(A).
TEST(CentredFrame, HessianInCoordinatesIsTheLocalOneThroughTheChainRule) {
  const CentredFrame frame(Eigen::Vector3d(300, -120, 8));
  Vector6d xi0;
  xi0 << 0.4, -0.2, 0.05, 0.01, -0.02, 0.3;  // the local pose at the minimum
  Matrix6d B = Matrix6d::Identity();
  B.topRightCorner<3, 3>() << 0.3, 0.1, 0, -0.2, 0.4, 0.1, 0, 0.2, 0.5;
  const Matrix6d A = B * B.transpose() + Matrix6d::Identity();  // positive definite, coupled
  const auto score = [&](const Vector6d& xi) {
    const Vector6d local = to_pose6(frame.local(to_isometry(Pose6::from_vector(xi)))).vector() - xi0;
    return 0.5 * local.dot(A * local);
  };
  const Vector6d at = to_pose6(frame.coordinates(to_isometry(Pose6::from_vector(xi0)))).vector();
  ASSERT_LT(score(at), 1e-12);
  const double h = 1e-4;
  Matrix6d numeric;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      Vector6d pp = at, pm = at, mp = at, mm = at;
      pp(i) += h, pp(j) += h, pm(i) += h, pm(j) -= h, mp(i) -= h, mp(j) += h, mm(i) -= h, mm(j) -= h;
      numeric(i, j) = (score(pp) - score(pm) - score(mp) + score(mm)) / (4 * h * h);
    }
  const Matrix6d analytic = frame.hessian_in_coordinates(A, to_isometry(Pose6::from_vector(at)));
  EXPECT_LT((analytic - numeric).norm(), 1e-4 * numeric.norm()) << analytic << "\n\n" << numeric;
  EXPECT_GT((analytic - A).norm(), 10.0) << "a rotation moves the translation by 300 m lever arms";
  EXPECT_TRUE(CentredFrame().hessian_in_coordinates(A, Eigen::Isometry3d::Identity()).isApprox(A));
}

}  // namespace
}  // namespace sextant
