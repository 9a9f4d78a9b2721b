// Matcher::share_reference (matcher.hpp): odometry's wide-basin recovery registers against the model
// its first try built. An ML-NDT matcher takes another's model only when its settings build the same
// one, and a registration against the shared model is the registration against its own, bit for bit.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace sextant
