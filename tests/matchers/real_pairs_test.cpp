// ML-NDT on the shared real pairs (data/README.md): the KITTI pair from identity (no trusted ground
// truth: checked by cross-method consensus), the fast_gicp Velodyne pair (p_target = T·p_source), and
// PCL's room scans from the tutorial guess.
// Settings for these ~70–120k-point outdoor scans (the thesis' q = 8, n = 4 was tuned on ~20k-point
// hannover scans, whose finest cells are far smaller than 100 m scenes' 2–4 m): n = 6 (finest
// cells ≈ 0.6–1 m), each finest-layer term truncated at eᵀC⁻¹e = 16 and unmatched points charged
// the same (robust to moving objects and non-overlap), every input point used.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "icp/kd_tree.hpp"
#include "pose_errors.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/ndt_matcher.hpp"
#include "sextant/matchers/samplers.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant {
namespace {

// The thesis' settings with the trust-region Newton step (the library's defaults before they moved to
// the `default` preset): what the measurements in these tests' comments were taken with.
constexpr const char* kThesisTrustRegion = "{preset: thesis, step_control: trust_region_last}";
constexpr const char* kOutdoor =
    "{layers: 6, max_distance: 16, unmatched_penalty: 16, bounds_quantile: 0, solver: ";

struct Error {
  double metres, degrees;
};

Error difference(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Eigen::Isometry3d E = a.inverse() * b;
  return {translation_norm(E), rotation_angle(E) * 180.0 / M_PI};
}

RegistrationResult align(const PointCloud& ref, const PointCloud& in, const std::string& matcher,
                         const std::string& settings, const std::string& sampler, const std::string& sampling,
                         const Eigen::Isometry3d& initial) {
  Rng rng(1);
  auto m = make_matcher(matcher, YAML::Load(settings));
  return match_pair(*m, *make_sampler(sampler, YAML::Load(sampling)), ref, in, initial, rng).result;
}

struct KittiPair {
  std::string dir = std::string(SEXTANT_DATA_DIR) + "/kitti00_pair/";
  PointCloud ref = read_cloud(dir + "000000.xyz32.bin");
  PointCloud in = read_cloud(dir + "000001.xyz32.bin");
};

/// The KITTI pair's result of every independent matcher from identity: ML-NDT (Newton, LM), ICP
/// point-to-plane (ours), PCL's GICP.
std::vector<std::pair<std::string, Eigen::Isometry3d>> kitti_every_matcher(const KittiPair& p) {
  std::vector<std::pair<std::string, Eigen::Isometry3d>> poses;
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  for (const char* solver : {"newton", "lm"}) {
    const RegistrationResult r =
        align(p.ref, p.in, "mlndt", std::string(kOutdoor) + solver + "}", "all", "{}", I);
    EXPECT_TRUE(r.converged) << solver << ": " << r.summary();
    poses.emplace_back(std::string("mlndt_") + solver, r.T);
  }
  const std::string gbs = "{cell_size: 0.5, max_per_cell: 3}";
  const RegistrationResult icp =
      align(p.ref, p.in, "icp_p2l", "{max_correspondence_distance: 1.0}", "gbs", gbs, I);
  EXPECT_TRUE(icp.converged) << icp.summary();
  poses.emplace_back("icp_p2l", icp.T);
  const RegistrationResult gicp = align(p.ref, p.in, "pcl_gicp", "{}", "gbs", gbs, I);
  EXPECT_TRUE(gicp.converged) << gicp.summary();
  poses.emplace_back("pcl_gicp", gicp.T);
  return poses;
}

// The KITTI pair has no trusted ground truth (data/README.md: the derived file is withdrawn). What
// holds instead is cross-method consensus: four independent matchers from identity agree with one
// another to 3 cm / 0.1° (measured: within 5 mm), on about 0.68 m forward motion.
TEST(RealPairs, KittiEveryMatcherAgreesFromIdentity) {
  const KittiPair p;
  const auto poses = kitti_every_matcher(p);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_NEAR(poses[i].second.translation().x(), 0.68, 0.05) << poses[i].first;
    for (std::size_t j = i + 1; j < poses.size(); ++j) {
      const Error e = difference(poses[i].second, poses[j].second);
      EXPECT_LT(e.metres, 0.03) << poses[i].first << " vs " << poses[j].first;
      EXPECT_LT(e.degrees, 0.1) << poses[i].first << " vs " << poses[j].first;
    }
  }
}

/// Median distance from the input's off-ground points beyond 20 m (mapped by T) to their nearest
/// reference point: a registration-free measure of how well T aligns the scans' structure.
double median_structure_gap(const PointCloud& ref, const PointCloud& in, const Eigen::Isometry3d& T) {
  const KdTree tree(ref.points());
  std::vector<float> gaps;
  for (const Eigen::Vector3f& p : in.points()) {
    if (p.norm() < 20.0f || p.z() < -1.4f) continue;  // the sensor is 1.73 m above the road
    KdTree::Neighbour n;
    if (tree.nearest(T.cast<float>() * p, 1.0f, &n)) gaps.push_back(std::sqrt(n.squared_distance));
  }
  if (gaps.empty()) return std::numeric_limits<double>::infinity();
  std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
  return gaps[gaps.size() / 2];
}

// Why the pair's derived "ground truth" was withdrawn (data/README.md): it assumed the scans are
// frames 0 and 1 of sequence 00, and the scans' own far structure (walls, poles, trees, no ground)
// contradicts it. The registered pose aligns them about twice as tightly as the withdrawn pose
// (measured: median gap 8.8 cm against 16 cm; sweeping x alone with its rotation puts the minimum
// at 0.68 m). The file is read here only to show that it is wrong.
TEST(RealPairs, KittiScansContradictTheWithdrawnDerivedPose) {
  const KittiPair p;
  const Eigen::Isometry3d withdrawn = test::read_transform(p.dir + "T_velo0_from_velo1_DERIVED.txt");
  const RegistrationResult r =
      align(p.ref, p.in, "mlndt", std::string(kOutdoor) + "lm}", "all", "{}", Eigen::Isometry3d::Identity());
  ASSERT_TRUE(r.converged) << r.summary();
  const double registered = median_structure_gap(p.ref, p.in, r.T);
  const double derived = median_structure_gap(p.ref, p.in, withdrawn);
  EXPECT_LT(registered, 0.7 * derived) << registered << " m vs " << derived << " m";
}

/// ML-NDT from identity on the Velodyne pair (all points) with each solver.
std::vector<Eigen::Isometry3d> velodyne_with_each_solver(const std::string& settings) {
  const std::string dir = std::string(SEXTANT_DATA_DIR) + "/velodyne_pair/";
  const PointCloud ref = read_cloud(dir + "fast_gicp_251370668.pcd");
  const PointCloud in = read_cloud(dir + "fast_gicp_251371071.pcd");
  std::vector<Eigen::Isometry3d> poses;
  for (const char* solver : {"newton", "lm", "ceres"}) {
    const RegistrationResult r =
        align(ref, in, "mlndt", settings + solver + "}", "all", "{}", Eigen::Isometry3d::Identity());
    EXPECT_TRUE(r.converged) << solver << ": " << r.summary();
    poses.push_back(r.T);
  }
  return poses;
}

// On real data with the outdoor truncation (max_distance, unmatched_penalty) the three solvers
// minimise the same objective, which is piecewise: LM and Ceres' LM agree to 1 mm / 0.01°;
// Newton's steps stop on a neighbouring piece (measured 1.1 mm / 0.015° from LM). On smooth
// synthetic data all three agree to 1 mm / 0.01° (Mlndt.RecoversKnownTransformWithEverySolver).
// Without the precision stage: Ceres refines on one of its two grids only (precision_stage.hpp).
TEST(RealPairs, SolversAgreeOnTruncatedObjective) {
  const std::vector<Eigen::Isometry3d> poses = velodyne_with_each_solver(
      "{layers: 6, max_distance: 16, unmatched_penalty: 16, epsilon: 1.0e-7, max_iterations: 100, "
      "precision_min_cell: 0, solver: ");
  const Error lm_ceres = difference(poses[1], poses[2]);
  EXPECT_LT(lm_ceres.metres, 1e-3);
  EXPECT_LT(lm_ceres.degrees, 0.01);
  const Error newton_lm = difference(poses[0], poses[1]);
  EXPECT_LT(newton_lm.metres, 3e-3);
  EXPECT_LT(newton_lm.degrees, 0.03);
}

TEST(RealPairs, VelodyneFromIdentity) {
  const std::string dir = std::string(SEXTANT_DATA_DIR) + "/velodyne_pair/";
  const Eigen::Isometry3d truth = test::read_transform(dir + "fast_gicp_relative.txt");
  const PointCloud ref = read_cloud(dir + "fast_gicp_251370668.pcd");
  const PointCloud in = read_cloud(dir + "fast_gicp_251371071.pcd");
  for (const char* solver : {"newton", "lm"}) {
    const RegistrationResult r = align(ref, in, "mlndt", std::string(kOutdoor) + solver + "}", "all", "{}",
                                       Eigen::Isometry3d::Identity());
    EXPECT_TRUE(r.converged) << solver << ": " << r.summary();
    const Error e = difference(truth, r.T);
    EXPECT_LT(e.metres, 0.05) << solver;
    EXPECT_LT(e.degrees, 0.3) << solver;
  }
}

// The room scans have no ground truth. From the tutorial guess (yaw 0.6931 rad, t = (1.79387,
// 0.720047, 0)) ML-NDT with the thesis' pyramid (q = 8, n = 4, plain eq. 3.11) must converge,
// and agree with a point-to-plane ICP refinement started at its result to 10 cm / 1° (the scans
// are noisy; PCL's NDT reaches t ≈ (1.97, 0.06, 0.01), yaw 40.8°, from the same guess).
TEST(RealPairs, RoomScansFromTutorialGuess) {
  const std::string dir = std::string(SEXTANT_DATA_DIR) + "/pcl_room_scan/";
  const PointCloud ref = read_cloud(dir + "room_scan1.pcd");
  const PointCloud in = read_cloud(dir + "room_scan2.pcd");
  const Eigen::Isometry3d guess =
      Eigen::Translation3d(1.79387, 0.720047, 0) * Eigen::AngleAxisd(0.6931, Eigen::Vector3d::UnitZ());
  const RegistrationResult r = align(ref, in, "mlndt", kThesisTrustRegion, "all", "{}", guess);
  ASSERT_TRUE(r.converged) << r.summary();
  const RegistrationResult icp = align(ref, in, "icp_p2l", "{max_correspondence_distance: 0.5}", "gbs",
                                       "{cell_size: 0.2, max_per_cell: 3}", r.T);
  ASSERT_TRUE(icp.converged) << icp.summary();
  const Error e = difference(icp.T, r.T);
  EXPECT_LT(e.metres, 0.10);
  EXPECT_LT(e.degrees, 1.0);
  EXPECT_NEAR(r.T.translation().x(), 1.97, 0.1);  // PCL NDT's order of magnitude
  EXPECT_NEAR(r.T.translation().y(), 0.06, 0.1);
}

// Newton's step control (issue 11) on the Velodyne pair from identity with the thesis' settings
// (q = 8, n = 4, plain eq. 3.11) and GBS (1 m cells, ≤ 5 points each). Measured: LM 11.5 cm / 0.29°;
// Newton with the default trust region 12.8 cm / 0.17°; with the Armijo line search 21.7 cm / 1.71°;
// the plain step of eq. (3.16) 160 cm / 9.4° after the 50-iteration cap (the thesis-faithful variant,
// still available as step_control: none).
TEST(RealPairs, NewtonStepControlOnVelodyneFromIdentity) {
  const std::string dir = std::string(SEXTANT_DATA_DIR) + "/velodyne_pair/";
  const Eigen::Isometry3d truth = test::read_transform(dir + "fast_gicp_relative.txt");
  const PointCloud ref = read_cloud(dir + "fast_gicp_251370668.pcd");
  const PointCloud in = read_cloud(dir + "fast_gicp_251371071.pcd");
  const auto run = [&](const std::string& settings) {
    return difference(truth, align(ref, in, "mlndt", settings, "gbs", "{}", Eigen::Isometry3d::Identity()).T);
  };
  const Error lm = run("{preset: thesis, solver: lm}");
  const Error trust = run("{preset: thesis, solver: newton, step_control: trust_region_last}");
  const Error explicit_trust =
      run("{solver: newton, step_control: trust_region_last, unmatched_penalty: 50, max_distance: .inf, "
          "bounds_quantile: 0, min_relative_spread: 0, refine_first: false, precision_min_cell: 0}");
  const Error line_search = run("{preset: thesis, solver: newton, step_control: line_search}");
  const Error plain = run("{preset: thesis}");  // the step as printed
  EXPECT_LT(lm.metres, 0.15);
  EXPECT_LT(trust.metres, 1.2 * lm.metres);  // LM-like
  EXPECT_LT(trust.degrees, 0.5);
  EXPECT_EQ(trust.metres, explicit_trust.metres);
  EXPECT_LT(line_search.metres, 0.30);
  EXPECT_GT(plain.metres, 1.0);  // the undamped update as printed still diverges here
}

// The library's defaults are the `default` preset; `thesis` pins every key they set differently.
TEST(MlndtPresets, LibraryDefaultsAreTheDefaultPresetAndThesisPinsTheThesis) {
  const MlndtSettings library;
  const MlndtSettings none = read_mlndt_settings(YAML::Load("{}"), "x");
  const MlndtSettings preset = read_mlndt_settings(YAML::Load("{preset: default}"), "x");
  for (const MlndtSettings* s : {&library, &none, &preset}) {
    EXPECT_EQ(s->optimizer.solver, SolverKind::kLevenbergMarquardt);
    EXPECT_EQ(s->pyramid.layers, 4);
    EXPECT_EQ(s->pyramid.division, 8);
    EXPECT_EQ(s->start_layer, 2);
    EXPECT_EQ(s->max_distance, 16.0);
    EXPECT_EQ(s->unmatched_penalty, 16.0);
    EXPECT_EQ(s->truncated_layers, 1);
    EXPECT_EQ(s->optimizer.iterations_per_stage, 3);
  }
  const MlndtSettings thesis = read_mlndt_settings(YAML::Load("{preset: thesis}"), "x");
  EXPECT_EQ(thesis.optimizer.solver, SolverKind::kNewton);
  EXPECT_EQ(thesis.optimizer.step_control, StepControl::kNone);
  EXPECT_TRUE(std::isinf(thesis.max_distance));
  EXPECT_EQ(thesis.unmatched_penalty, 50.0);
  EXPECT_EQ(thesis.pyramid.layers, 4);
  EXPECT_EQ(thesis.start_layer, 2);
  EXPECT_EQ(thesis.optimizer.max_iterations, 50);
  // A key beside the preset overrides it.
  EXPECT_EQ(read_mlndt_settings(YAML::Load("{preset: thesis, solver: lm}"), "x").optimizer.solver,
            SolverKind::kLevenbergMarquardt);
  // The YAML `preset:` is the preset in code (mlndt_presets.hpp), field for field where they differ.
  const MlndtSettings code = *mlndt_preset("thesis");
  EXPECT_EQ(code.optimizer.function_tolerance, thesis.optimizer.function_tolerance);
  EXPECT_EQ(code.pyramid.bounds_quantile, thesis.pyramid.bounds_quantile);
  EXPECT_EQ(code.refine_first, thesis.refine_first);
  EXPECT_EQ(mlndt_preset("outdoor")->pyramid.layers,
            read_mlndt_settings(YAML::Load("{preset: outdoor}"), "x").pyramid.layers);
  EXPECT_EQ(mlndt_preset("default")->threads, 0) << "every thread TBB allows";
  EXPECT_FALSE(mlndt_preset("fastest").has_value());
  try {
    read_mlndt_settings(YAML::Load("{layers: 5,\n preset: fastest}"), "exp.yaml");
    ADD_FAILURE() << "an unknown preset must be an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("exp.yaml:", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("unknown preset 'fastest' (known: default, thesis, outdoor)"),
              std::string::npos)
        << e.what();
  }
}

// The legacy boolean and the named setting: line_search: true = step_control: line_search; both at
// once is an error naming the key.
TEST(RealPairs, StepControlSettingIsNamed) {
  EXPECT_EQ(read_mlndt_settings(YAML::Load("{line_search: true}"), "x").optimizer.step_control,
            StepControl::kLineSearch);
  EXPECT_EQ(read_mlndt_settings(YAML::Load("{line_search: false}"), "x").optimizer.step_control,
            StepControl::kNone);
  EXPECT_EQ(read_mlndt_settings(YAML::Load("{}"), "x").optimizer.step_control, StepControl::kTrustRegionLast);
  EXPECT_EQ(read_ndt_settings(YAML::Load("{}"), "x").optimizer.step_control, StepControl::kLineSearch);
  EXPECT_EQ(read_ndt_settings(YAML::Load("{step_control: none}"), "x").optimizer.step_control,
            StepControl::kNone);
  EXPECT_THROW(read_mlndt_settings(YAML::Load("{line_search: true, step_control: none}"), "x"), InputError);
  EXPECT_THROW(read_mlndt_settings(YAML::Load("{step_control: wolfe}"), "x"), InputError);
}

// E5 on the shared real pairs (§5.1.2.1: FbML-NDT from a zero guess reaches "a few cm in three
// iterations"): FbML-NDT from the identity, every input point offered to the feature extraction.
// Measured with the thesis' pyramid (q = 8, n = 4): Velodyne 7.3 cm / 0.45° in 10 iterations,
// KITTI 1.9 cm / 0.04° from the matchers' consensus (no trusted ground truth) in 9; with the outdoor
// settings (n = 6, truncation) Velodyne 1.9 cm / 0.03° in 19 iterations. So: a few cm, but in
// 9–19 iterations, not three (ML-NDT runs three per coarse layer before the last).
TEST(RealPairs, FbmlndtFromZeroGuess) {
  const KittiPair k;
  const std::string dir = std::string(SEXTANT_DATA_DIR) + "/velodyne_pair/";
  const Eigen::Isometry3d vtruth = test::read_transform(dir + "fast_gicp_relative.txt");
  const PointCloud vref = read_cloud(dir + "fast_gicp_251370668.pcd");
  const PointCloud vin = read_cloud(dir + "fast_gicp_251371071.pcd");
  const auto run = [](const std::string& settings, const PointCloud& ref, const PointCloud& in) {
    Rng rng(1);
    auto m = make_matcher("fbmlndt", YAML::Load(settings));
    return match_pair(*m, *make_sampler("all", YAML::Node()), ref, in, Eigen::Isometry3d::Identity(), rng)
        .result;
  };
  const RegistrationResult velodyne = run(kThesisTrustRegion, vref, vin);
  ASSERT_TRUE(velodyne.converged) << velodyne.summary();
  EXPECT_LT(difference(vtruth, velodyne.T).metres, 0.10);
  EXPECT_LT(difference(vtruth, velodyne.T).degrees, 0.6);
  EXPECT_LE(velodyne.iterations, 12);
  // From the zero guess, which is no guess: the pyramid from start layer 2 (refine_first off).
  const RegistrationResult outdoor =
      run("{layers: 6, max_distance: 16, unmatched_penalty: 16, refine_first: false}", vref, vin);
  EXPECT_LT(difference(vtruth, outdoor.T).metres, 0.03);
  // KITTI has no trusted ground truth: compare with the matchers' consensus (ML-NDT, LM, outdoor).
  const RegistrationResult kitti = run(kThesisTrustRegion, k.ref, k.in);
  ASSERT_TRUE(kitti.converged) << kitti.summary();
  const Eigen::Isometry3d consensus =
      align(k.ref, k.in, "mlndt", std::string(kOutdoor) + "lm}", "all", "{}", Eigen::Isometry3d::Identity())
          .T;
  EXPECT_LT(difference(consensus, kitti.T).metres, 0.10);
  EXPECT_LT(difference(consensus, kitti.T).degrees, 0.3);
}

}  // namespace
}  // namespace sextant
