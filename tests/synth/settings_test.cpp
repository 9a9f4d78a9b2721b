// Campus settings: defaults are valid, YAML maps onto them, bad values name file, line and key.
#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/synth/settings.hpp"
#include "sextant/synth/yaml.hpp"

namespace sextant::synth {
namespace {

std::string error_of(const std::string& yaml) {
  try {
    read_campus_settings(YAML::Load(yaml), "campus.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CampusSettings, DefaultsAreValidAndThesisLike) {
  const CampusSettings s;
  std::string why;
  EXPECT_TRUE(s.valid(&why)) << why;
  EXPECT_EQ(s.trajectory.scans, 468);
  EXPECT_DOUBLE_EQ(s.trajectory.sharp_turn_deg, 51.5);
  EXPECT_EQ(s.odometry.model, "thesis");
}

TEST(CampusSettings, YamlOverridesAndRoundTripsThroughTheResolvedText) {
  const CampusSettings s = read_campus_settings(
      YAML::Load("trajectory:\n  scans: 12\nsensor:\n  max_range: 25.5\nodometry:\n  model: gaussian\n"),
      "x.yaml");
  EXPECT_EQ(s.trajectory.scans, 12);
  EXPECT_DOUBLE_EQ(s.sensor.max_range, 25.5);
  EXPECT_EQ(s.odometry.model, "gaussian");
  std::uint64_t seed = 0;
  const CampusSettings back =
      read_campus_settings(YAML::Load(campus_settings_yaml(s, 77)), "campus.yaml", &seed);
  EXPECT_EQ(seed, 77u);
  EXPECT_EQ(campus_settings_yaml(back, seed), campus_settings_yaml(s, 77));
  EXPECT_EQ(campus_hash(back, seed), campus_hash(s, 77));
  EXPECT_NE(campus_hash(s, 77), campus_hash(s, 78));
}

TEST(CampusSettings, UnknownKeyIsRejectedWithFileLineAndKey) {
  const std::string e = error_of("sensor:\n  max_range: 30\n  max_rnage: 20\n");
  EXPECT_NE(e.find("campus.yaml"), std::string::npos) << e;
  EXPECT_NE(e.find("line 3"), std::string::npos) << e;
  EXPECT_NE(e.find("max_rnage"), std::string::npos) << e;
  EXPECT_NE(error_of("wrld:\n  border: 20\n").find("wrld"), std::string::npos);
}

TEST(CampusSettings, NegativeRangeZeroScansAndWrongTypesAreRejected) {
  const std::string range = error_of("sensor:\n  max_range: -5\n");
  EXPECT_NE(range.find("max_range"), std::string::npos) << range;
  EXPECT_NE(range.find("line 2"), std::string::npos) << range;
  const std::string scans = error_of("trajectory:\n  scans: 0\n");
  EXPECT_NE(scans.find("scans must be in [1, 100000]"), std::string::npos) << scans;
  // Issue 64, class 7: a route of two billion scans would only exhaust the memory.
  const std::string too_many = error_of("trajectory:\n  scans: 2000000000\n");
  EXPECT_NE(too_many.find("scans must be in [1, 100000]"), std::string::npos) << too_many;
  EXPECT_NE(error_of("trajectory:\n  scans: many\n").find("scans"), std::string::npos);
  const std::string first = error_of("trajectory:\n  scans: 20\n  first_scans: 21\n");
  EXPECT_NE(first.find("first_scans must be in [0, scans]"), std::string::npos) << first;
  EXPECT_NE(error_of("odometry:\n  model: kalman\n").find("model"), std::string::npos);
  EXPECT_NE(error_of("sensor:\n  range_noise: -0.1\n").find("range_noise"), std::string::npos);
}

TEST(CampusSettings, ValidExplainsTheFirstProblem) {
  CampusSettings s;
  s.sensor.min_range = 50.0;
  std::string why;
  EXPECT_FALSE(s.valid(&why));
  EXPECT_NE(why.find("sensor.max_range"), std::string::npos) << why;
}

}  // namespace
}  // namespace sextant::synth
