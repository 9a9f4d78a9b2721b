// Loop-closure candidates along a trajectory that revisits its start, and the acceptance test.
#include <cmath>

#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/posegraph/loop_closure.hpp"
#include "sextant/posegraph/yaml.hpp"

namespace sextant {
namespace {

/// A circle of radius 20 m driven twice, 60 poses a lap (≈ 2.1 m apart).
std::vector<Eigen::Isometry3d> two_laps() {
  std::vector<Eigen::Isometry3d> poses;
  for (int k = 0; k < 120; ++k) {
    const double a = 2 * M_PI * k / 60.0;
    poses.push_back(to_isometry({20 * std::cos(a), 20 * std::sin(a), 0, 0, 0, a + M_PI / 2}));
  }
  return poses;
}

TEST(LoopClosure, CandidatesAppearWhereTheTrajectoryComesBack) {
  LoopClosureSettings s;
  s.radius = 1.0;  // neighbours are 2.1 m apart: only the same place one lap later
  s.min_index_gap = 30;
  s.min_path_gap = 60.0;
  s.stride = 5;
  const auto c = find_loop_closure_candidates(two_laps(), s);
  ASSERT_FALSE(c.empty());
  EXPECT_EQ(c.front().j, 60u);  // the second lap starts at pose 60
  EXPECT_EQ(c.front().i, 0u);
  for (std::size_t k = 0; k < c.size(); ++k) {
    EXPECT_LT(c[k].i, c[k].j);
    EXPECT_GE(c[k].j - c[k].i, 30u);
    EXPECT_LE(c[k].distance, 1.0);
    // Revisits pair up with the same place one lap earlier.
    EXPECT_EQ((c[k].j - c[k].i) % 60, 0u) << c[k].i << " " << c[k].j;
    EXPECT_LT((c[k].guess.translation()).norm(), 1e-9);
    if (k > 0) {
      EXPECT_GE(c[k].j - c[k - 1].j, 5u);
    }
  }
  // No candidate on the first lap (the circle's other side is 40 m away).
  s.radius = 30.0;
  s.min_path_gap = 130.0;  // more than a lap
  for (const auto& x : find_loop_closure_candidates(two_laps(), s)) EXPECT_GE(x.j, 62u);
}

TEST(LoopClosure, AcceptanceFollowsConvergenceScoreAndCorrection) {
  LoopClosureSettings s;
  LoopClosureCandidate c{10, 70, 1.0, to_isometry({1, 0, 0, 0, 0, 0.1})};
  RegistrationResult r;
  r.converged = true;
  r.why = Termination::kConverged;
  r.T = to_isometry({1.5, 0.2, 0, 0, 0, 0.12});
  r.H = 1000 * Matrix6d::Identity();
  r.input_points = 1000;
  r.matched_points = 900;
  r.score = 900 * 2.0;
  LoopClosureDecision d = judge_loop_closure(r, c, s);
  EXPECT_TRUE(d.accepted) << d.reason;
  EXPECT_NEAR(d.mean_score, 2.0, 1e-12);
  EXPECT_NEAR(d.matched_fraction, 0.9, 1e-12);
  EXPECT_GT(d.information.determinant(), 0.0);

  RegistrationResult bad = r;
  bad.converged = false;
  bad.why = Termination::kMaxIterations;
  EXPECT_FALSE(judge_loop_closure(bad, c, s).accepted);
  bad = r;
  bad.score = 900 * 10.0;  // poor fit
  EXPECT_FALSE(judge_loop_closure(bad, c, s).accepted);
  bad = r;
  bad.T = to_isometry({15, 0, 0, 0, 0, 0.1});  // jumped 14 m from the guess
  d = judge_loop_closure(bad, c, s);
  EXPECT_FALSE(d.accepted);
  EXPECT_NEAR(d.correction_m, 14.0, 1e-9);
  bad = r;
  bad.H(2, 2) = 0.0;  // an unconstrained direction
  EXPECT_EQ(judge_loop_closure(bad, c, s).reason, "Hessian not positive definite");
}

TEST(LoopClosure, SettingsAreCheckedWithFileLineAndKey) {
  const YAML::Node node = YAML::Load("radius: 5\nstride: 0\n");
  try {
    (void)read_loop_closure_settings(node, "e20.yaml");
    FAIL() << "stride 0 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("stride"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)read_loop_closure_settings(YAML::Load("radius: 5\nradious: 3\n"), "e20.yaml"),
               InputError);
  EXPECT_DOUBLE_EQ(read_loop_closure_settings(YAML::Load("radius: 5\n"), "e20.yaml").radius, 5.0);
}

}  // namespace
}  // namespace sextant
