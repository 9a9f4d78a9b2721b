// Matchers and samplers by value (matcher_spec.hpp) and read from YAML once (read_matcher_spec).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "pose_errors.hpp"
#include "sextant/core/error.hpp"
#include "sextant/matchers/matcher_choice.hpp"
#include "sextant/matchers/matcher_spec.hpp"
#include "sextant/matchers/mlndt_presets.hpp"
#include "sextant/matchers/yaml.hpp"
#include "test_clouds.hpp"

namespace sextant {
namespace {

TEST(MatcherSpec, TheCatalogueNamesEveryMatcherAndSamplerOnce) {
  const std::vector<std::string> matchers{"fbmlndt", "icp_p2l",  "icp_p2p", "mlndt",
                                          "ndt",     "pcl_gicp", "pcl_icp", "pcl_ndt"};
  EXPECT_EQ(matcher_names(), matchers);
  EXPECT_EQ(sampler_names(), (std::vector<std::string>{"all", "fbs", "gbs", "random", "regular"}));
  for (const std::string& name : matcher_names()) {
    const MatcherSpec spec = read_matcher_spec(name, YAML::Node(), "<test>");
    EXPECT_EQ(spec.name(), name);
    EXPECT_EQ(make_matcher(spec)->name(), name);  // the type built is the one named
    const MatcherTraits by_name = matcher_traits(name), by_spec = spec.traits();
    EXPECT_EQ(by_name.judges_itself, by_spec.judges_itself) << name;
    EXPECT_EQ(by_name.has_wide_basin, by_spec.has_wide_basin) << name;
    EXPECT_EQ(by_name.layer_pyramid, last_layer(spec) > 0) << name;
  }
  for (const std::string& name : sampler_names())
    EXPECT_EQ(make_sampler(read_sampler_spec(name, YAML::Node(), "<test>"))->name(), name);
  EXPECT_EQ(MatcherSpec().name(), "mlndt");  // the default spec: the default ML-NDT on GBS
  EXPECT_EQ(SamplerSpec().name(), "gbs");
  EXPECT_FALSE(matcher_traits("no_such_matcher").judges_itself);
}

TEST(MatcherSpec, UnknownNamesAndBadSettingsAreInputErrorsNamingThem) {
  try {
    read_matcher_spec("mlnd", YAML::Node(), "exp.yaml");
    FAIL() << "an unknown matcher was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "exp.yaml");
    EXPECT_NE(std::string(e.what()).find("unknown matcher 'mlnd' (known: fbmlndt icp_p2l"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(read_sampler_spec("grid", YAML::Node(), "exp.yaml"), InputError);
  try {
    read_matcher_spec("mlndt", YAML::Load("{layers: 3,\n start_layer: 9}"), "exp.yaml");
    FAIL() << "a start layer past the last was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "exp.yaml");
    EXPECT_NE(std::string(e.what()).find("start_layer"), std::string::npos) << e.what();
  }
}

TEST(MatcherSpec, EveryConstructorRejectsInvalidSettingsTheSameWay) {
  MlndtSettings mlndt;
  mlndt.start_layer = mlndt.pyramid.layers + 1;
  std::string why;
  ASSERT_FALSE(MatcherSpec(mlndt).valid(&why));
  EXPECT_THROW(MlndtMatcher{mlndt}, std::invalid_argument);
  EXPECT_THROW(matcher_choice(mlndt), std::invalid_argument);
  FbmlndtSettings fbmlndt;
  fbmlndt.mlndt = mlndt;
  EXPECT_THROW(FbmlndtMatcher{fbmlndt}, std::invalid_argument);
  NdtSettings ndt;
  ndt.optimizer.max_iterations = 0;
  EXPECT_THROW(NdtMatcher{ndt}, std::invalid_argument);
  IcpP2lSettings icp;
  icp.max_correspondence_distance = -1.0;
  EXPECT_THROW(make_matcher(icp), std::invalid_argument);
  GridSamplerSettings gbs;
  gbs.cell_size = 0.0;
  EXPECT_THROW(GridSampler{gbs}, std::invalid_argument);
  EXPECT_THROW(sampler_factory(gbs), std::invalid_argument);
  RandomSamplerSettings random;
  random.fraction = 1.5;
  EXPECT_THROW(RandomSampler{random}, std::invalid_argument);
  RegularSamplerSettings regular;
  regular.step = 0;
  EXPECT_THROW(RegularSampler{regular}, std::invalid_argument);
}

TEST(MatcherSpec, APresetReadFromYamlIsThePresetStructAndRegistersTheSameBits) {
  const MatcherSpec read = read_matcher_spec("mlndt", YAML::Load("{preset: thesis}"), "<test>");
  const MlndtSettings* s = read.get<MlndtSettings>();
  ASSERT_NE(s, nullptr);
  const MlndtSettings thesis = *mlndt_preset("thesis");
  EXPECT_EQ(s->unmatched_penalty, thesis.unmatched_penalty);
  EXPECT_EQ(s->max_distance, thesis.max_distance);
  EXPECT_EQ(s->refine_first, thesis.refine_first);
  EXPECT_EQ(s->precision.min_cell, thesis.precision.min_cell);

  Rng rng(3), rng2(4);
  const PointCloud reference = test::yard(rng);
  const Eigen::Isometry3d T = test::pose(0.8, -0.5, 0.05, 1, -1, 5);
  const PointCloud input = test::yard(rng2).transformed(T.inverse());
  const auto register_with = [&](const MatcherSpec& spec) {
    const auto m = make_matcher(spec);
    m->set_reference(reference);
    return m->align(input, Eigen::Isometry3d::Identity());
  };
  const RegistrationResult a = register_with(read), b = register_with(thesis);
  EXPECT_LT(test::translation_error(a.T, T), 0.05);
  EXPECT_EQ(a.T.matrix(), b.T.matrix());  // bit for bit
  EXPECT_EQ(a.iterations, b.iterations);
}

TEST(MatcherSpec, TheWideBasinVariantAndTheStartLayer) {
  MlndtSettings own;
  own.wide_basin.enabled = true;
  own.wide_basin.yaw_step_deg = 5.0;
  const MatcherSpec own_wide = with_wide_basin(own);
  const MlndtSettings* kept = own_wide.get<MlndtSettings>();
  ASSERT_NE(kept, nullptr);
  EXPECT_EQ(kept->wide_basin.yaw_step_deg, 5.0);  // its own wide-basin settings stay
  MlndtSettings plain;
  plain.wide_basin.yaw_step_deg = 7.0;  // not enabled: the wide basin's defaults are used
  const MatcherSpec plain_wide = with_wide_basin(plain);
  const MlndtSettings* wide = plain_wide.get<MlndtSettings>();
  ASSERT_NE(wide, nullptr);
  EXPECT_TRUE(wide->wide_basin.enabled);
  EXPECT_EQ(wide->wide_basin.yaw_step_deg, WideBasinSettings{}.yaw_step_deg);
  const MatcherSpec fb = with_wide_basin(FbmlndtSettings{});
  EXPECT_TRUE(fb.get<FbmlndtSettings>()->mlndt.wide_basin.enabled);
  const MatcherSpec icp = with_wide_basin(IcpP2pSettings{});
  EXPECT_EQ(icp.name(), "icp_p2p");

  const MatcherChoice choice = matcher_choice(plain);
  EXPECT_FALSE(choice.own_wide_basin);
  ASSERT_TRUE(static_cast<bool>(choice.make_wide));
  EXPECT_FALSE(static_cast<bool>(matcher_choice(IcpP2pSettings{}).make_wide));
  EXPECT_TRUE(matcher_choice(own).own_wide_basin);

  MatcherSpec layered = MlndtSettings{};
  EXPECT_TRUE(set_start_layer(layered, 3));
  EXPECT_EQ(layered.get<MlndtSettings>()->start_layer, 3);
  MatcherSpec fb_layered = FbmlndtSettings{};
  EXPECT_TRUE(set_start_layer(fb_layered, 1));
  EXPECT_EQ(fb_layered.get<FbmlndtSettings>()->mlndt.start_layer, 1);
  MatcherSpec flat = NdtSettings{};
  EXPECT_FALSE(set_start_layer(flat, 2));
  EXPECT_EQ(last_layer(flat), 0);
  EXPECT_EQ(last_layer(layered), MlndtSettings{}.pyramid.layers);
}

}  // namespace
}  // namespace sextant
