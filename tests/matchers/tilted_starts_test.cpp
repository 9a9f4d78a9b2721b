// The wide basin's tilted starts (mlndt_global_init.hpp, issue 62): a narrow view carried by hand whose
// guess is off in pitch, which the level grid of yaw × x/y does not bring back, with a known answer
// (the synthetic campus seen by a rosette over 70° × 77°, carried on foot).
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "pose_errors.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/registration_quality.hpp"
#include "sextant/matchers/samplers.hpp"
#include "sextant/matchers/yaml.hpp"
#include "sextant/synth/campus.hpp"

namespace sextant {
namespace {

const synth::Campus& walk(const std::string& pattern = "rosette") {
  synth::CampusSettings s;
  s.trajectory.scans = 4200;  // the route at 0.3 m per scan
  s.trajectory.first_scans = 12;
  s.trajectory.platform = "handheld";
  s.trajectory.sensor_height = 1.5;
  s.trajectory.scan_period = 0.5;
  s.trajectory.sharp_turn_deg = 10.0;
  s.sensor.pattern = pattern;
  s.sensor.body_length = s.sensor.body_width = 0.0;
  static std::map<std::string, synth::Campus> campuses;
  if (!campuses.count(pattern)) campuses.emplace(pattern, synth::generate_campus(s, 1));
  return campuses.at(pattern);
}

struct Registered {
  RegistrationResult result;
  Eigen::Isometry3d truth;
  PointCloud input;  ///< the input's GBS sample, which was registered
};

/// Scan 11 registered against scan 10 by the wide basin with `wide_basin` (YAML map) from the true pose
/// turned by `degrees` about the input's own `axis` and moved by `offset`.
Registered register_turned(const Eigen::Vector3d& axis, double degrees, const std::string& wide_basin,
                           const std::string& pattern = "rosette",
                           const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  const synth::Campus& campus = walk(pattern);
  const Eigen::Isometry3d truth = relative(campus.ground_truth[10], campus.ground_truth[11]);
  Eigen::Isometry3d guess = truth;
  guess.linear() = truth.linear() * Eigen::AngleAxisd(degrees * kRadPerDeg, axis).toRotationMatrix();
  guess.translation() += offset;
  const auto wide = make_matcher("mlndt", YAML::Load("{wide_basin: " + wide_basin + "}"), "test");
  wide->set_reference(campus.scan(10).cloud);
  Rng rng(1);
  const SampledInput sample = sample_input(GridSampler(), campus.scan(11).cloud, rng);  // as `match` samples
  return {wide->align(sample.points, guess), truth, sample.points};
}

TEST(TiltedStarts, SettingsAreReadAndValidated) {
  const MlndtSettings s = read_mlndt_settings(
      YAML::Load("{wide_basin: {tilt_step_deg: 5, tilt_range_deg: 10, tilt_candidates: 3}}"), "t");
  EXPECT_EQ(s.wide_basin.tilt_step_deg, 5.0);
  EXPECT_EQ(s.wide_basin.tilt_range_deg, 10.0);
  EXPECT_EQ(s.wide_basin.tilt_candidates, 3);
  EXPECT_EQ(s.wide_basin.tilted_hypotheses(), 37L * (5 * 5 - 1));  // yaw ±180° every 10°
  EXPECT_EQ(read_mlndt_settings(YAML::Load("{wide_basin: {tilt_candidates: 0}}"), "t")
                .wide_basin.tilted_hypotheses(),
            0);
  EXPECT_THROW(read_mlndt_settings(YAML::Load("{wide_basin: {tilt_candidates: -1}}"), "t"), InputError);
  EXPECT_THROW(read_mlndt_settings(YAML::Load("{wide_basin: {tilt_step_deg: 0}}"), "t"), InputError);
  EXPECT_THROW(read_mlndt_settings(YAML::Load("{wide_basin: {tilt_range_deg: 91}}"), "t"), InputError);
}

TEST(TiltedStarts, AGuessTwentyDegreesOffInPitchIsRecovered) {
  const Eigen::Vector3d pitch = Eigen::Vector3d::UnitY();
  const Registered level = register_turned(pitch, 20.0, "{tilt_candidates: 0}");
  EXPECT_GT(test::rotation_error(level.truth, level.result.T), 5.0 * kRadPerDeg)
      << "the level grid alone was expected to fail";
  const Registered tilted = register_turned(pitch, 20.0, "{}");
  EXPECT_LT(test::translation_error(tilted.truth, tilted.result.T), 0.05) << tilted.result.summary();
  EXPECT_LT(test::rotation_error(tilted.truth, tilted.result.T), 0.5 * kRadPerDeg) << tilted.result.summary();
  EXPECT_TRUE(assess_registration(tilted.result, tilted.input, QualitySettings{}).trusted());
}

TEST(TiltedStarts, AreNotTriedWhereALevelStartFindsTheAnswer) {
  // 20° of yaw: the level grid holds the answer, and the tilted starts would only add rivals.
  const Eigen::Vector3d yaw = Eigen::Vector3d::UnitZ();
  const Registered level = register_turned(yaw, 20.0, "{tilt_candidates: 0}");
  const Registered tilted = register_turned(yaw, 20.0, "{}");
  EXPECT_LT(test::rotation_error(tilted.truth, tilted.result.T), 0.5 * kRadPerDeg);
  EXPECT_TRUE(tilted.result.T.matrix() == level.result.T.matrix()) << "the same runs, bit for bit";
  EXPECT_EQ(tilted.result.alternatives.size(), level.result.alternatives.size());
}

TEST(TiltedStarts, AreNotTriedForAViewAllAround) {
  // A spinning lidar's guess 40 m off: beyond the level grid, nothing passes, and still no tilted start
  // runs (its pyramid brings a tilt of 30° back by itself).
  const Eigen::Vector3d pitch = Eigen::Vector3d::UnitY(), far(40.0, 0.0, 0.0);
  const Registered level = register_turned(pitch, 0.0, "{tilt_candidates: 0}", "spinning", far);
  ASSERT_FALSE(assess_registration(level.result, level.input, QualitySettings{}).trusted());
  const Registered tilted = register_turned(pitch, 0.0, "{}", "spinning", far);
  EXPECT_TRUE(tilted.result.T.matrix() == level.result.T.matrix());
  EXPECT_EQ(tilted.result.alternatives.size(), level.result.alternatives.size());
  // The same guess for the rosette does run them.
  const Registered narrow_level = register_turned(pitch, 0.0, "{tilt_candidates: 0}", "rosette", far);
  ASSERT_FALSE(assess_registration(narrow_level.result, narrow_level.input, QualitySettings{}).trusted());
  const Registered narrow = register_turned(pitch, 0.0, "{}", "rosette", far);
  EXPECT_GT(narrow.result.alternatives.size(), narrow_level.result.alternatives.size());
}

}  // namespace
}  // namespace sextant
