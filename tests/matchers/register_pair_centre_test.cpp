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

}  // namespace
}  // namespace sextant
