// Matcher::share_reference (matcher.hpp): odometry's wide-basin recovery registers against the model
// its first try built. An ML-NDT matcher takes another's model only when its settings build the same
// one, and a registration against the shared model is the registration against its own, bit for bit.
// With the model it takes the runs already made on it (run_memo.hpp): a run repeated on the same input
// is taken, not made again, and the result is the one a matcher without them computes.
#include <gtest/gtest.h>

#include "mlndt/mlndt_global_init.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/ndt_matcher.hpp"
#include "test_clouds.hpp"

namespace sextant {
namespace {

TEST(ShareReference, WideBasinMatcherRegistersOnTheFirstTrysModel) {
  Rng rng(3), rng2(4);
  const PointCloud reference = test::yard(rng, 2);
  const Eigen::Isometry3d truth = to_isometry(Pose6{1.2, -0.8, 0.0, 0.0, 0.0, 0.2});
  const PointCloud input = test::yard(rng2, 2).transformed(truth.inverse());
  MlndtMatcher first;  // the defaults
  first.set_reference(reference);
  MlndtSettings wide;
  wide.wide_basin.enabled = true;
  MlndtMatcher shared(wide), own(wide);
  ASSERT_TRUE(shared.share_reference(first));
  EXPECT_EQ(&shared.layers(), &first.layers()) << "the same grids, not a copy";
  own.set_reference(reference);
  const RegistrationResult a = shared.align(input, Eigen::Isometry3d::Identity());
  const RegistrationResult b = own.align(input, Eigen::Isometry3d::Identity());
  ASSERT_TRUE(a.converged) << a.summary();
  EXPECT_LT((a.T.translation() - truth.translation()).norm(), 0.05);
  EXPECT_TRUE(a.T.matrix() == b.T.matrix()) << a.T.matrix() << "\n" << b.T.matrix();
  EXPECT_EQ(a.score, b.score);
  EXPECT_EQ(a.iterations, b.iterations);
}

TEST(ShareReference, RefusedWhenTheModelWouldDiffer) {
  Rng rng(3);
  const PointCloud reference = test::yard(rng, 2);
  MlndtMatcher built;
  MlndtMatcher unbuilt;
  EXPECT_FALSE(MlndtMatcher().share_reference(unbuilt)) << "nothing built yet";
  built.set_reference(reference);
  MlndtSettings finer;
  finer.pyramid.layers = 5;
  MlndtSettings no_precision;
  no_precision.precision.min_cell = 0.0;
  MlndtSettings robust_box;
  robust_box.pyramid.bounds_quantile = 0.0;
  for (const MlndtSettings& other : {finer, no_precision, robust_box}) {
    MlndtMatcher m(other);
    m.set_reference(reference);
    const std::vector<NdtGrid>* own = &m.layers();
    EXPECT_FALSE(m.share_reference(built));
    EXPECT_EQ(&m.layers(), own) << "nothing changed";
  }
  NdtMatcher ndt;
  EXPECT_FALSE(ndt.share_reference(built)) << "another kind of matcher builds its own model";
  MlndtSettings other_solver;
  other_solver.optimizer.max_iterations = 10;
  EXPECT_TRUE(MlndtMatcher(other_solver).share_reference(built)) << "the optimiser does not change the model";
}

/// Everything a registration reports but the time it took, compared bit for bit.
void expect_same_registration(const RegistrationResult& a, const RegistrationResult& b) {
  EXPECT_TRUE(a.T.matrix() == b.T.matrix()) << a.T.matrix() << "\n" << b.T.matrix();
  EXPECT_TRUE(a.H == b.H);
  EXPECT_EQ(a.score, b.score);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(a.why, b.why);
  EXPECT_EQ(a.matched_points, b.matched_points);
  ASSERT_EQ(a.alternatives.size(), b.alternatives.size());
  for (std::size_t k = 0; k < a.alternatives.size(); ++k)
    EXPECT_TRUE(a.alternatives[k].T.matrix() == b.alternatives[k].T.matrix()) << "alternative " << k;
}

struct RunsFixture {
  PointCloud reference, input, other_input;
  Eigen::Isometry3d guess = to_isometry(Pose6{1.0, -0.6, 0.0, 0.0, 0.0, 0.15});
  RunsFixture() {
    Rng rng(3), rng2(4), rng3(5);
    reference = test::yard(rng, 2);
    const Eigen::Isometry3d truth = to_isometry(Pose6{1.2, -0.8, 0.0, 0.0, 0.0, 0.2});
    input = test::yard(rng2, 2).transformed(truth.inverse());
    other_input = test::yard(rng3, 2).transformed(truth.inverse());
  }
};

TEST(ShareReference, TheWideBasinFromTheGuessTakesTheFirstTrysRuns) {
  const RunsFixture f;
  MlndtMatcher first;  // the defaults: the pyramid and the last layer from the guess, the precision stage
  first.set_reference(f.reference);
  const RegistrationResult first_try = first.align(f.input, f.guess);
  ASSERT_TRUE(first_try.converged) << first_try.summary();
  ASSERT_FALSE(first.precision_layers().empty()) << "the fixture must exercise the precision stage";
  EXPECT_EQ(first.reused_runs(), 0);
  MlndtSettings wide;
  wide.wide_basin.enabled = true;
  MlndtMatcher shared(wide), own(wide);
  ASSERT_TRUE(shared.share_reference(first));
  own.set_reference(f.reference);
  const RegistrationResult a = shared.align(f.input, f.guess);
  const RegistrationResult b = own.align(f.input, f.guess);
  EXPECT_EQ(own.reused_runs(), 0);
  // The pyramid and the last layer from the guess; also the precision stage when the same run wins,
  // and the hypothesis at the guess itself when it is a candidate (it starts at the last layer).
  EXPECT_GE(shared.reused_runs(), 2);
  expect_same_registration(a, b);
  // Aligned again from the same guess, every run is known; from another start, none is.
  const RegistrationResult again = shared.align(f.input, f.guess);
  const auto hypotheses = wide_basin_starts(shared.layers(), f.input, f.guess, wide.wide_basin).size() - 1;
  ASSERT_GT(hypotheses, static_cast<std::size_t>(wide.wide_basin.candidates)) << "and some above the horizon";
  const int runs =
      2 + static_cast<int>(hypotheses) + 1;  // the guess' two, the hypotheses', the precision stage
  EXPECT_EQ(shared.reused_runs(), runs);
  expect_same_registration(again, b);
  const Eigen::Isometry3d elsewhere = to_isometry(Pose6{0.5, 0.2, 0.0, 0.0, 0.0, -0.1});
  const RegistrationResult moved = shared.align(f.input, elsewhere);
  expect_same_registration(moved, own.align(f.input, elsewhere));
}

TEST(ShareReference, RunsAreNotTakenForAnotherInputModelOrObjective) {
  const RunsFixture f;
  MlndtMatcher first;
  first.set_reference(f.reference);
  first.align(f.input, f.guess);
  MlndtSettings wide;
  wide.wide_basin.enabled = true;
  {  // another input on the same model
    MlndtMatcher shared(wide), own(wide);
    ASSERT_TRUE(shared.share_reference(first));
    own.set_reference(f.reference);
    expect_same_registration(shared.align(f.other_input, f.guess), own.align(f.other_input, f.guess));
    EXPECT_EQ(shared.reused_runs(), 0);
  }
  {  // another optimiser: the same model, other runs
    MlndtSettings looser = wide;
    looser.optimizer.epsilon = 1e-3;
    MlndtMatcher shared(looser), own(looser);
    ASSERT_TRUE(shared.share_reference(first));
    own.set_reference(f.reference);
    expect_same_registration(shared.align(f.input, f.guess), own.align(f.input, f.guess));
    EXPECT_EQ(shared.reused_runs(), 0);
  }
  {  // another reference: the first matcher's runs were made on the model it replaces
    Rng rng(9);
    const PointCloud moved_reference = test::yard(rng, 2);
    first.set_reference(moved_reference);
    MlndtMatcher shared(wide), own(wide);
    ASSERT_TRUE(shared.share_reference(first));
    own.set_reference(moved_reference);
    expect_same_registration(shared.align(f.input, f.guess), own.align(f.input, f.guess));
    EXPECT_EQ(shared.reused_runs(), 0);
  }
}

}  // namespace
}  // namespace sextant
