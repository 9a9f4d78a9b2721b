// What a registration ends with beside its trust: FbML-NDT checked against ML-NDT on real pairs, and an
// empty reference model named by its cause (issues 22, 23).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include "pose_errors.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/matchers/fbmlndt_matcher.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/register_pair.hpp"
#include "sextant/matchers/registration_quality.hpp"
#include "sextant/matchers/sampler.hpp"
#include "sextant/matchers/yaml.hpp"
#include "sextant_test/random_draws.hpp"

namespace sextant {
namespace {

// FbML-NDT never ends far from ML-NDT on the same pair: its result is checked on GBS points
// (FbmlndtSettings::verify). On the real outdoor pairs from the identity both end within 10 cm.
TEST(FbmlndtVerify, EndsWhereMlndtEndsOnRealPairs) {
  const std::string data = std::string(SEXTANT_DATA_DIR) + "/";
  for (const auto& [ref_file, in_file] :
       {std::pair<std::string, std::string>{"velodyne_pair/fast_gicp_251370668.pcd",
                                            "velodyne_pair/fast_gicp_251371071.pcd"},
        {"kitti00_pair/000000.xyz32.bin", "kitti00_pair/000001.xyz32.bin"}}) {
    const PointCloud ref = read_cloud(data + ref_file), in = read_cloud(data + in_file);
    const auto all = make_sampler("all");
    Eigen::Isometry3d poses[2];
    int k = 0;
    for (const char* matcher : {"mlndt", "fbmlndt"}) {
      const auto m = make_matcher(matcher, YAML::Load("{wide_basin: {}}"));
      Rng rng(1);
      const PairMatch r = match_pair(*m, *all, ref, in, Eigen::Isometry3d::Identity(), rng);
      EXPECT_TRUE(r.result.quality.trusted()) << matcher << " on " << ref_file << ": " << r.result.summary();
      poses[k++] = r.result.T;
    }
    EXPECT_LT(test::translation_error(poses[0], poses[1]), 0.10) << ref_file;
  }
}

TEST(FbmlndtVerify, FollowsRefineFirstUnlessGiven) {
  EXPECT_TRUE(read_fbmlndt_settings(YAML::Load("{}"), "<test>").verify);
  EXPECT_FALSE(read_fbmlndt_settings(YAML::Load("{preset: thesis}"), "<test>").verify);
  EXPECT_TRUE(read_fbmlndt_settings(YAML::Load("{preset: thesis, verify: true}"), "<test>").verify);
}

}  // namespace
}  // namespace sextant

namespace sextant {
namespace {

// Issue 23: a grid of too many cells and a reference without a single Gaussian both said
// empty_input; each now names its cause.
TEST(EmptyReferenceModel, NamesTheCause) {
  PointCloud yard;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j)
      yard.push_back({static_cast<float>(i) * 0.5f, static_cast<float>(j) * 0.5f,
                      static_cast<float>((i * j) % 7) * 0.1f});
  const auto ndt = make_matcher("ndt", YAML::Load("{cell_size: 0.001}"));
  ndt->set_reference(yard);
  EXPECT_EQ(ndt->align(yard, Eigen::Isometry3d::Identity()).why, Termination::kGridTooLarge);
  MlndtMatcher mlndt;
  mlndt.set_reference(PointCloud({{0, 0, 0}, {5, 0, 0}, {0, 5, 0}, {0, 0, 5}}));  // no cell with 5 points
  const RegistrationResult sparse = mlndt.align(yard, Eigen::Isometry3d::Identity());
  EXPECT_EQ(sparse.why, Termination::kNoGaussians);
  EXPECT_EQ(to_string(sparse.why), "no_gaussians");
  mlndt.set_reference(PointCloud());
  EXPECT_EQ(mlndt.align(yard, Eigen::Isometry3d::Identity()).why, Termination::kEmptyInput);
}

}  // namespace
}  // namespace sextant
