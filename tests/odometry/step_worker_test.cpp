// One odometry step's recovery (odometry/src/step_worker.hpp) with a scripted matcher: each start
// gets the answer the script gives it, so the trust rules are tested on their own.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <utility>

#include "sextant/core/pose.hpp"
#include "sextant/matchers/matcher_choice.hpp"
#include "sextant/odometry/sequence_trust.hpp"
#include "step_worker.hpp"

namespace sextant {
namespace {

/// A pose `x` metres ahead.
Eigen::Isometry3d metres_ahead(double x) {
  return Eigen::Isometry3d(Eigen::Translation3d(x, 0.0, 0.0));
}

/// A converged registration at `T` that matched `overlap` of the input and fits `fit` × the
/// prediction, every direction equally constrained.
RegistrationResult scripted_answer(const Eigen::Isometry3d& T, std::size_t points, double overlap,
                                   double fit) {
  RegistrationResult r;
  r.T = T;
  r.converged = true;
  r.why = Termination::kConverged;
  r.H = Matrix6d::Identity();
  r.input_points = points;
  r.matched_points = static_cast<std::size_t>(overlap * static_cast<double>(points));
  r.predicted_matched_score = 3.0;
  r.mean_matched_score = 3.0 * fit;
  return r;
}

/// What a registration from a start (keyed by its forward metres) answers: the pose, its overlap and
/// fit, and optionally a second solution the same registration reached (an alternative).
struct Scripted {
  double x = 0.0, overlap = 0.9, fit = 1.0;
  double alternative_x = 0.0, alternative_fit = 0.0;  ///< alternative_fit 0: none
};

class ScriptedMatcher final : public Matcher {
 public:
  explicit ScriptedMatcher(std::map<double, Scripted> script) : script_(std::move(script)) {}
  std::string name() const override { return "scripted"; }
  void set_reference(const PointCloud& /*reference*/) override {}
  RegistrationResult align(const PointCloud& input, const Eigen::Isometry3d& initial) override {
    const Scripted& s = script_.at(initial.translation().x());
    RegistrationResult r = scripted_answer(metres_ahead(s.x), input.size(), s.overlap, s.fit);
    if (s.alternative_fit > 0.0)
      r.alternatives.push_back(
          scripted_answer(metres_ahead(s.alternative_x), input.size(), s.overlap, s.alternative_fit));
    return r;
  }

 private:
  std::map<double, Scripted> script_;
};

PointCloud scripted_cloud() {
  PointCloud c;
  for (int i = 0; i < 100; ++i) c.push_back({static_cast<float>(i % 10), static_cast<float>(i / 10), 0.f});
  return c;
}

/// The step from the guess 8.6 m forward, whose first registration matches too little, recovered from
/// the guess and from no motion with `from_guess` and `from_no_motion` as the wide basin's answers.
OdometryStep recovered(const Scripted& from_guess, const Scripted& from_no_motion) {
  const std::map<double, Scripted> first{{8.6, {7.16, 0.3, 0.97}}};  // low overlap: recovery runs
  const std::map<double, Scripted> wide{{8.6, from_guess}, {0.0, from_no_motion}};
  OdometrySettings s;
  s.registration.matcher.make = [first] { return std::make_unique<ScriptedMatcher>(first); };
  s.registration.matcher.make_wide = [wide] { return std::make_unique<ScriptedMatcher>(wide); };
  s.registration.sampler = all_points_sampler_factory();
  odometry_detail::StepWorker worker(s);
  const PointCloud reference = scripted_cloud(), input = scripted_cloud();
  OdometryStep step = worker.first_try(reference, input, metres_ahead(8.6), 1);
  EXPECT_FALSE(step.trusted()) << "the script's first registration matches 30 %";
  worker.recover(step, reference, input, {metres_ahead(8.6), metres_ahead(0.0)}, 1, SequenceTrust());
  return step;
}

// The wide basin from the guess finds the right pose (8.16 m) and one 1.01 m short of it (7.15 m),
// fitting about as well: ambiguous. From no motion it then finds only the short one (7.16 m, 0.995 m
// from the right one: inside the ambiguity tolerance of it). That does not settle the dispute: the step
// stays untrusted and says it is ambiguous. (The campus route in 150 scans, seed 4, step 102: trusted
// 1.006 m off before.)
TEST(StepWorker, ReachingADisputedPoseAgainDoesNotSettleTheDispute) {
  const OdometryStep step = recovered({8.16, 0.9, 0.90, 7.15, 0.97}, {7.165, 0.9, 0.97});
  EXPECT_FALSE(step.trusted());
  EXPECT_NE(step.quality.reason.find("ambiguous"), std::string::npos) << step.quality.reason;
  EXPECT_EQ(step.recovery, "least_suspect");
}

// The control: without the dispute (the wide basin from the guess finds the short pose alone, with too
// little overlap), the answer from no motion is trusted and chained.
TEST(StepWorker, AnUndisputedRecoveryIsTrusted) {
  const OdometryStep step = recovered({7.15, 0.3, 0.97}, {7.165, 0.9, 0.97});
  EXPECT_TRUE(step.trusted()) << step.quality.reason;
  EXPECT_EQ(step.recovery, "wide_basin");
  EXPECT_NEAR(step.relative.translation().x(), 7.165, 1e-12);
}

}  // namespace
}  // namespace sextant
