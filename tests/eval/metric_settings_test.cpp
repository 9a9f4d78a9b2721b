#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/eval/yaml.hpp"

namespace sextant {
namespace {

TEST(MetricSettings, SuccessPresetOrMap) {
  const SuccessCriterion preset =
      read_success_criterion(YAML::Load("translation_200cm_rotation_10deg"), "x.yaml");
  EXPECT_DOUBLE_EQ(preset.max_translation_cm, 200.0);
  EXPECT_DOUBLE_EQ(preset.max_rotation_deg, 10.0);
  const SuccessCriterion map =
      read_success_criterion(YAML::Load("{max_translation_cm: 30, require_converged: true}"), "x.yaml");
  EXPECT_DOUBLE_EQ(map.max_translation_cm, 30.0);
  EXPECT_TRUE(map.require_converged);
  EXPECT_DOUBLE_EQ(read_success_criterion(YAML::Node(), "x.yaml").max_translation_cm, 50.0);
  EXPECT_THROW(read_success_criterion(YAML::Load("bogus"), "x.yaml"), InputError);
}

TEST(MetricSettings, RegistrationStatsSettings) {
  const RegistrationStatsSettings s =
      read_registration_stats_settings(YAML::Load("axes: uos\nsuccess: {max_translation_cm: 200, "
                                                  "max_rotation_deg: 10}\nerrors_of_successes_only: true"),
                                       "e02.yaml");
  EXPECT_EQ(s.axes, AxisConvention::uos);
  EXPECT_DOUBLE_EQ(s.success.max_rotation_deg, 10.0);
  EXPECT_TRUE(s.errors_of_successes_only);
}

TEST(MetricSettings, ErrorsNameFileLineAndKey) {
  try {
    read_rpe_settings(YAML::Load("unit: frames\ndelta: 2\ndleta: 3"), "e19.yaml");
    FAIL() << "unknown key accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "e19.yaml");
    EXPECT_EQ(e.where(), "line 3");
    EXPECT_NE(e.problem().find("dleta"), std::string::npos);
  }
  try {
    read_rpe_settings(YAML::Load("unit: frames\ndelta: 2.5"), "e19.yaml");
    FAIL() << "fractional frame delta accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "line 2");
    EXPECT_NE(e.problem().find("delta"), std::string::npos);
  }
  EXPECT_THROW(read_rpe_settings(YAML::Load("unit: miles"), "e19.yaml"), InputError);
  EXPECT_THROW(read_rpe_settings(YAML::Load("delta: abc"), "e19.yaml"), InputError);
  EXPECT_THROW(read_registration_stats_settings(YAML::Load("axes: ned"), "e02.yaml"), InputError);
  EXPECT_THROW(read_success_criterion(YAML::Load("{max_translation_cm: -3}"), "e02.yaml"), InputError);
}

TEST(MetricSettings, RpeAndKitti) {
  const RpeSettings rpe =
      read_rpe_settings(YAML::Load("{unit: meters, delta: 10, all_pairs: true, tolerance: 0.5}"), "f");
  EXPECT_EQ(rpe.unit, RpeSettings::Unit::meters);
  EXPECT_DOUBLE_EQ(rpe.delta, 10.0);
  EXPECT_TRUE(rpe.all_pairs);
  const KittiDriftSettings k =
      read_kitti_drift_settings(YAML::Load("{segment_lengths: [100, 200], step: 5}"), "f");
  EXPECT_EQ(k.segment_lengths, (std::vector<double>{100, 200}));
  EXPECT_EQ(k.step, 5u);
  EXPECT_THROW(read_kitti_drift_settings(YAML::Load("{segment_lengths: []}"), "f"), InputError);
  EXPECT_THROW(read_kitti_drift_settings(YAML::Load("{step: 0}"), "f"), InputError);
}

}  // namespace
}  // namespace sextant
