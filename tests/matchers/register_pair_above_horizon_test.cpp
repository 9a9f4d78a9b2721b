// `sextant match`'s answers confirmed by the points above the horizon (register_pair.hpp,
// horizon_check.hpp), with a scripted matcher (sextant_test/scripted_matcher.hpp): nothing else bounds a
// pair's answer.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>

#include "sextant/matchers/register_pair.hpp"
#include "sextant_test/scripted_matcher.hpp"

namespace sextant {
namespace {

using test::Scripted;
using test::ScriptedMatcher;

/// A pair registered without a guess: the wide basin's search answers 2.37 m (overlap 0.56, fit 1.21)
/// and the input's points above the horizon, registered alone from there, answer `above`; the whole scan
/// from 4.02 m ends at 4.09 m, from 3.6 m back at 2.40 m.
PairRegistration searched_short_of_the_motion(const Scripted& above,
                                              SensorKind sensor = SensorKind::spinning) {
  PairRegistrationRequest request;
  request.sensor = sensor;  // a few points that stand for a spinning lidar's scan
  request.matcher.name = "scripted";
  request.matcher.make = [above] {
    return std::make_unique<ScriptedMatcher>(
        std::map<double, Scripted>{{2.37, above}, {4.02, {4.09, 0.67, 1.25}}, {3.6, {2.40, 0.56, 1.21}}});
  };
  request.matcher.make_wide = [] {
    return std::make_unique<ScriptedMatcher>(std::map<double, Scripted>{{0.0, {2.37, 0.56, 1.21}}});
  };
  request.sampler = sampler_factory(AllPointsSettings{});
  return register_pair(test::scan_above_and_below(), test::scan_above_and_below(), request);
}

// MulRan keyframes 13 → 14 as 16 rings: an answer 2.37 m on where the car moved 4.0 m, whose points above
// the horizon move on 1.65 m and the whole scan from there ends at 4.09 m, is not trusted; where they
// stay, match too little to say, or the whole scan comes back from where they rest, it is.
TEST(RegisterPair, AnAnswerThePointsAboveTheHorizonLeaveIsNotTrusted) {
  const PairRegistration moved_on = searched_short_of_the_motion({4.02, 0.88, 0.98});
  EXPECT_EQ(moved_on.match.result.quality.trust, Trust::kSuspect);
  EXPECT_NE(moved_on.match.result.quality.reason.find("registered alone from it, move 1.65 m"),
            std::string::npos)
      << moved_on.match.result.quality.reason;
  EXPECT_TRUE(searched_short_of_the_motion({2.45, 0.88, 0.98}).match.result.quality.trusted());
  EXPECT_TRUE(searched_short_of_the_motion({4.02, 0.3, 0.98}).match.result.quality.trusted());
  EXPECT_TRUE(searched_short_of_the_motion({3.6, 0.88, 0.98}).match.result.quality.trusted());
}

// A solid-state lidar draws no rings that could hold the answer short: its points above the horizon are
// not asked, and the search's answer stands as the checks judged it.
TEST(RegisterPair, ASolidStateLidarsAnswerIsNotAskedAboveTheHorizon) {
  const PairRegistration solid = searched_short_of_the_motion({4.02, 0.88, 0.98}, SensorKind::solid_state);
  EXPECT_TRUE(solid.match.result.quality.trusted()) << solid.match.result.quality.reason;
  ASSERT_TRUE(solid.sensor.has_value());
  EXPECT_EQ(solid.sensor->kind, SensorKind::solid_state);
  const PairRegistration measured = searched_short_of_the_motion({4.02, 0.88, 0.98}, SensorKind::automatic);
  ASSERT_TRUE(measured.sensor.has_value());
  EXPECT_EQ(measured.sensor->kind, detect_sensor(test::scan_above_and_below()).kind);
}

}  // namespace
}  // namespace sextant
