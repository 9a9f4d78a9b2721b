// NDT and ML-NDT on synthetic pairs with a known transform: recovery, solver agreement,
// DOF mask, the long-range claim, degenerate input.
#include <gtest/gtest.h>

#include <cmath>

#include "ndt/ndt_score.hpp"
#include "pose_errors.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/units.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/ndt_matcher.hpp"
#include "sextant/matchers/samplers.hpp"
#include "sextant/matchers/yaml.hpp"
#include "test_clouds.hpp"

namespace sextant {
namespace {

/// Reference and input of one scene seen from two poses: input = T⁻¹·scene (fresh sampling),
/// so that p_ref = T·p_input.
struct Pair {
  PointCloud reference, input;
  Eigen::Isometry3d T;
};

Pair make_pair(const Eigen::Isometry3d& T, std::uint64_t seed = 1) {
  Rng rng(seed);
  Pair p;
  p.T = T;
  p.reference = test::yard(rng);
  Rng rng2(seed + 100);
  const PointCloud scene = test::yard(rng2);
  Rng rng3(seed + 200);
  const PointCloud sampled = scene.subset(GridSampler(GridSamplerSettings{1.0, 5, 3}).select(scene, rng3));
  p.input = sampled.transformed(T.inverse());
  return p;
}

RegistrationResult run(const std::string& method, const std::string& yaml, const Pair& p,
                       const Eigen::Isometry3d& init = Eigen::Isometry3d::Identity()) {
  auto matcher = make_matcher(method, YAML::Load(yaml));
  matcher->set_reference(p.reference);
  return matcher->align(p.input, init);
}

TEST(Mlndt, RecoversKnownTransformWithEverySolver) {
  const Pair p = make_pair(test::pose(1.2, -0.8, 0.1, 1, -1, 8));
  std::vector<RegistrationResult> results;
  // The plain Newton step (step_control: none) first, then LM, Ceres and the default Newton.
  for (const char* solver : {"newton, step_control: none", "lm", "ceres", "newton"}) {
    const RegistrationResult r =
        run("mlndt", std::string("{solver: ") + solver + ", epsilon: 1.0e-7, max_iterations: 100}", p);
    EXPECT_TRUE(r.converged) << solver << ": " << r.summary();
    EXPECT_LT(test::translation_error(r.T, p.T), 0.05) << solver;
    EXPECT_LT(test::rotation_error_deg(r.T, p.T), 0.3) << solver;
    EXPECT_FALSE(r.trace.empty());
    EXPECT_GT(r.matched_points, 100u);
    EXPECT_EQ(r.input_points, p.input.size());
    EXPECT_GT(r.H.trace(), 0.0);
    results.push_back(r);
  }
  // The solvers minimise the same objective: plain Newton, LM and Ceres agree to 1 mm / 0.01°;
  // Newton's default trust region stops where no damped step lowers the score any more, on a
  // neighbouring piece of the piecewise objective (measured 1.8 mm from plain Newton).
  for (std::size_t i = 1; i < 3; ++i) {
    EXPECT_LT(test::translation_error(results[0].T, results[i].T), 1e-3) << i;
    EXPECT_LT(test::rotation_error_deg(results[0].T, results[i].T), 0.01) << i;
  }
  EXPECT_LT(test::translation_error(results[0].T, results[3].T), 3e-3);
  EXPECT_LT(test::rotation_error_deg(results[0].T, results[3].T), 0.03);
}

// Known answers for the robust options: a point at the cell mean scores 0, so the whole score is
// the far point's term; a limit below it rejects exactly that point (no score, no gradient).
TEST(Mlndt, TruncationRejectsFarCorrespondencesAndDegenerateCellsAreDropped) {
  PointCloud ref;
  for (int i = 0; i < 200; ++i) {
    const float a = 0.01f * static_cast<float>(i);
    ref.push_back({0.5f + 0.1f * std::cos(7.0f * a), 0.5f + 0.1f * std::sin(5.0f * a),
                   0.5f + 0.1f * std::cos(3.0f * a)});
  }
  const NdtGrid grid = NdtGrid::build(ref, Eigen::Vector3d::Zero(), 1.0, Eigen::Vector3i::Ones());
  ASSERT_EQ(grid.gaussian_count(), 1u);
  PointCloud in;
  in.push_back({grid.gaussian(0).mean[0], grid.gaussian(0).mean[1], grid.gaussian(0).mean[2]});
  in.push_back({0.95f, 0.95f, 0.95f});
  const Vector6d zero = Vector6d::Zero();
  const ScoreEvaluation all = mahalanobis_score(grid, in, zero, Derivatives::kScore);
  EXPECT_EQ(all.matched, 2u);
  EXPECT_EQ(all.rejected, 0u);
  const double far = all.score;  // the first point contributes 0
  const ScoreEvaluation cut = mahalanobis_score(grid, in, zero, Derivatives::kHessian, 0.5 * far);
  EXPECT_EQ(cut.matched, 1u);
  EXPECT_EQ(cut.rejected, 1u);
  EXPECT_NEAR(cut.score, 0.0, 1e-9);
  EXPECT_LT(cut.gradient.norm(), 1e-6);

  PointCloud repeated(std::vector<Eigen::Vector3f>(10, Eigen::Vector3f(0.5f, 0.5f, 0.5f)));
  repeated.push_back({0.5f + 1e-5f, 0.5f, 0.5f});  // λmax ≈ 1e-11 m², below min_spread
  EXPECT_EQ(NdtGrid::build(repeated, Eigen::Vector3d::Zero(), 1.0, Eigen::Vector3i::Ones()).gaussian_count(),
            0u);
  CellStatsSettings keep;
  keep.min_spread = 0.0;
  EXPECT_EQ(
      NdtGrid::build(repeated, Eigen::Vector3d::Zero(), 1.0, Eigen::Vector3i::Ones(), keep).gaussian_count(),
      1u);
}

TEST(Mlndt, TraceFollowsLayerSchedule) {
  const Pair p = make_pair(test::pose(0.5, 0.3, 0, 0, 0, 3));
  const RegistrationResult r =
      run("mlndt", "{start_layer: 2, refine_first: false, precision_min_cell: 0}", p);
  ASSERT_GE(r.trace.size(), 7u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(r.trace[static_cast<std::size_t>(i)].layer, 2);
  for (int i = 3; i < 6; ++i) EXPECT_EQ(r.trace[static_cast<std::size_t>(i)].layer, 3);
  EXPECT_EQ(r.trace.back().layer, 4);
}

TEST(Ndt, RecoversKnownTransform) {
  const Pair p = make_pair(test::pose(0.6, -0.4, 0.05, 0.5, -0.5, 4));
  for (const char* yaml : {"{cell_size: 2.0}", "{cell_size: 2.0, trilinear: true}", "{}"}) {
    const RegistrationResult r = run("ndt", yaml, p);
    EXPECT_TRUE(r.converged) << yaml << ": " << r.summary();
    // The default cell (volume/64, 7 m here) is coarse: a few cm of bias from the different
    // point densities of reference and (GBS-sampled) input.
    EXPECT_LT(test::translation_error(r.T, p.T), 0.08) << yaml;
    EXPECT_LT(test::rotation_error_deg(r.T, p.T), 0.3) << yaml;
  }
}

TEST(Mlndt, DofMaskKeepsFixedParameters) {
  const Pair p = make_pair(test::pose(1.0, 0.7, 0, 0, 0, 6));
  const Eigen::Isometry3d init = test::pose(0, 0, 0.3, 0, 0, 0);  // z is wrong but fixed
  for (const char* solver : {"newton", "lm", "ceres"}) {
    const RegistrationResult r =
        run("mlndt", std::string("{dof: [x, y, yaw], solver: ") + solver + "}", p, init);
    const Pose6 est = to_pose6(r.T);
    EXPECT_DOUBLE_EQ(est.z, 0.3) << solver;
    EXPECT_NEAR(est.alpha, 0.0, 1e-12) << solver;
    EXPECT_NEAR(est.beta, 0.0, 1e-12) << solver;
    EXPECT_NEAR(est.gamma, 6 * kRadPerDeg, 1.0 * kRadPerDeg) << solver;
  }
  EXPECT_THROW(make_matcher("mlndt", YAML::Load("{dof: [x, q]}")), InputError);
}

TEST(Mlndt, LongRangeBeatsFixedCellNdt) {
  // The thesis' long-range claim (§3.2, chapter 5): from a zero initial guess ML-NDT recovers a
  // 15°, several-metre displacement that NDT at the finest layer's cell size does not.
  const Pair p = make_pair(test::pose(3.0, -2.0, 0.0, 0, 0, 15), 3);
  const RegistrationResult ml = run("mlndt", "{start_layer: 1}", p);
  EXPECT_LT(test::translation_error(ml.T, p.T), 0.1) << ml.summary();
  EXPECT_LT(test::rotation_error_deg(ml.T, p.T), 0.5);
  MlndtMatcher probe;
  probe.set_reference(p.reference);
  const double finest = probe.layers().back().cell_edge();
  const RegistrationResult ndt = run("ndt", "{cell_size: " + std::to_string(finest) + "}", p);
  EXPECT_TRUE(test::translation_error(ndt.T, p.T) > 0.5 || test::rotation_error_deg(ndt.T, p.T) > 2.0)
      << ndt.summary();
}

TEST(Registration, DegenerateInputNeverCrashes) {
  const Pair p = make_pair(test::pose(0.3, 0.2, 0, 0, 0, 2));
  PointCloud tiny;
  for (int i = 0; i < 3; ++i) tiny.push_back({float(i), 0, 0});
  PointCloud collinear, coplanar, far_away;
  for (int i = 0; i < 300; ++i) collinear.push_back({0.1f * i - 15, 0.5f, 1.0f});
  for (int i = 0; i < 400; ++i) coplanar.push_back({0.5f * (i % 20) - 5, 0.5f * (i / 20) - 5, 0.0f});
  for (int i = 0; i < 400; ++i) far_away.push_back({1000.0f + i, 1000.0f, 0.0f});
  Eigen::Isometry3d nan_guess = Eigen::Isometry3d::Identity();
  nan_guess.translation().x() = std::nan("");
  for (const char* method : {"mlndt", "ndt"}) {
    for (const char* solver : {"newton", "lm", "ceres"}) {
      if (std::string(method) == "ndt" && std::string(solver) == "ceres") continue;
      const std::string yaml = std::string("{solver: ") + solver + "}";
      const auto check = [&](const PointCloud& ref, const PointCloud& in, const Eigen::Isometry3d& init,
                             const char* what, bool must_fail) {
        auto m = make_matcher(method, YAML::Load(yaml));
        m->set_reference(ref);
        const RegistrationResult r = m->align(in, init);
        EXPECT_TRUE(is_finite(r.T)) << method << " " << solver << " " << what;
        EXPECT_TRUE(r.H.allFinite()) << method << " " << solver << " " << what;
        if (must_fail) {
          EXPECT_FALSE(r.converged) << method << " " << solver << " " << what << ": " << r.summary();
        }
      };
      check(p.reference, PointCloud(), Eigen::Isometry3d::Identity(), "empty input", true);
      check(PointCloud(), p.input, Eigen::Isometry3d::Identity(), "empty reference", true);
      check(tiny, p.input, Eigen::Isometry3d::Identity(), "too few reference points", true);
      check(p.reference, tiny, Eigen::Isometry3d::Identity(), "too few input points", true);
      check(p.reference, far_away, Eigen::Isometry3d::Identity(), "no overlap", true);
      check(p.reference, p.input, nan_guess, "NaN guess", true);
      check(collinear, collinear, Eigen::Isometry3d::Identity(), "collinear", false);
      check(coplanar, coplanar, Eigen::Isometry3d::Identity(), "coplanar", false);
    }
  }
}

}  // namespace
}  // namespace sextant
