// Every matcher's poses judged on the default ML-NDT's last layer (judged_matcher.hpp): on the real
// Velodyne pair, a pose at the reference passes the trust checks and one 3 m along the road does not,
// whichever matcher reported it; the matcher's own answer is left as it gave it.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "pose_errors.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/matchers/judged_matcher.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/matcher_choice.hpp"
#include "sextant/matchers/matcher_traits.hpp"
#include "sextant/matchers/registration_quality.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant {
namespace {

/// A matcher that answers its guess, converged, with a score and time of its own and no fit or
/// Hessian: what the trust checks knew of ICP's and the PCL peers' results.
class AnswersItsGuess final : public Matcher {
 public:
  std::string name() const override { return "answers_its_guess"; }
  void set_reference(const PointCloud& /*reference*/) override {}
  RegistrationResult align(const PointCloud& input, const Eigen::Isometry3d& initial) override {
    RegistrationResult r;
    r.T = initial;
    r.converged = true;
    r.why = Termination::kConverged;
    r.score = 7.0;
    r.seconds = 0.5;
    r.matched_points = input.size();  // every point has a correspondence within its search radius
    r.input_points = input.size();
    return r;
  }
};

struct JudgedVelodynePair {
  std::string dir = std::string(SEXTANT_DATA_DIR) + "/velodyne_pair/";
  PointCloud reference = read_cloud(dir + "fast_gicp_251370668.pcd");
  PointCloud input = read_cloud(dir + "fast_gicp_251371071.pcd");
  Eigen::Isometry3d truth = test::read_transform(dir + "fast_gicp_relative.txt");
};

RegistrationResult judged_at(Matcher& matcher, const JudgedVelodynePair& pair,
                             const Eigen::Isometry3d& pose) {
  matcher.set_reference(pair.reference);
  RegistrationResult r = matcher.align(pair.input, pose);
  r.quality = assess_registration(r, pair.input);
  return r;
}

TEST(JudgedMatcher, TrustsARightPoseAndNotOneSlidAlongTheRoad) {
  const JudgedVelodynePair pair;
  Eigen::Isometry3d slid = pair.truth;
  slid.translation().x() += 3.0;
  JudgedMatcher judged(std::make_unique<AnswersItsGuess>());
  const RegistrationResult right = judged_at(judged, pair, pair.truth);
  EXPECT_EQ(right.quality.trust, Trust::kOk) << right.quality.reason;
  EXPECT_GT(right.quality.fit_ratio, 0.8);
  EXPECT_LT(right.quality.fit_ratio, 1.3);
  EXPECT_GT(right.quality.constraint_ratio, 1e-3);
  // The matcher's own answer is kept: pose, score, time, no Hessian (R = H⁻¹ is its to give).
  EXPECT_TRUE(right.T.isApprox(pair.truth));
  EXPECT_EQ(right.score, 7.0);
  EXPECT_EQ(right.seconds, 0.5);
  EXPECT_TRUE(right.H.isZero(0.0));
  EXPECT_LT(right.matched_points, pair.input.size()) << "the judge's matches, not the matcher's";
  const RegistrationResult wrong = judged_at(judged, pair, slid);
  EXPECT_FALSE(wrong.quality.trusted()) << "3 m along the road";
  EXPECT_GT(wrong.quality.fit_ratio, 1.3);
  // Unjudged, the same 3 m answer passed: only its own correspondences' overlap was checked.
  AnswersItsGuess bare;
  EXPECT_TRUE(judged_at(bare, pair, slid).quality.trusted());
}

TEST(JudgedMatcher, WrapsOnlyTheMatchersThatDoNotJudgeThemselves) {
  EXPECT_TRUE(matcher_traits("mlndt").judges_itself);
  EXPECT_TRUE(matcher_traits("fbmlndt").judges_itself);
  for (const std::string& name : matcher_names()) {
    const MatcherChoice choice = matcher_choice(read_matcher_spec(name, YAML::Node(), "<test>"));
    const std::unique_ptr<Matcher> m = choice.make();
    EXPECT_EQ(dynamic_cast<JudgedMatcher*>(m.get()) == nullptr, matcher_traits(name).judges_itself) << name;
    EXPECT_EQ(static_cast<bool>(choice.make_wide), matcher_traits(name).has_wide_basin) << name;
    if (!matcher_traits(name).judges_itself) {
      EXPECT_EQ(m->name(), name);
    }
  }
  EXPECT_NE(dynamic_cast<JudgedMatcher*>(matcher_choice(IcpP2lSettings{}).make().get()), nullptr);
  EXPECT_EQ(judged(nullptr), nullptr);
}

}  // namespace
}  // namespace sextant
