// A real sequence without odometry gets one simulated from its reference with the campus' error
// model (kit/simulated_odometry_dataset.hpp), so E2 runs on real scans (issue 25).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "kit/dataset_source.hpp"
#include "kit/simulated_odometry_dataset.hpp"
#include "sextant/core/error.hpp"
#include "sextant/experiments/experiment_config.hpp"
#include "sextant/synth/odometry.hpp"
#include "test_helpers.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;
const fs::path kExcerpt = fs::path(SEXTANT_SOURCE_DIR) / "data" / "mulran_riverside02_excerpt";

synth::OdometrySettings exact_but_biased(double forward_bias) {
  synth::OdometrySettings s;
  s.bias_forward = forward_bias;
  s.bias_lateral = s.bias_heading_deg = 0.0;
  s.sigma_forward = s.sigma_lateral = s.sigma_heading_deg = 0.0;
  s.outlier_probability = 0.0;
  return s;
}

TEST(SimulatedOdometry, IncrementsAreTheReferencesCorruptedByTheModel) {
  const SimulatedOdometryDataset d(open_dataset(kExcerpt), exact_but_biased(0.5), 1);
  ASSERT_EQ(d.size(), 5u);
  EXPECT_TRUE(d.metadata().has_odometry);
  EXPECT_NE(d.metadata().notes.back().find("simulated from the reference"), std::string::npos);
  for (std::size_t i = 1; i < d.size(); ++i) {
    const synth::Increment2D truth = synth::planar_increment(*d.ground_truth(i - 1), *d.ground_truth(i));
    const synth::Increment2D odo = synth::planar_increment(*d.odometry(i - 1), *d.odometry(i));
    EXPECT_NEAR(odo.forward, truth.forward + 0.5, 1e-9) << i;  // the bias, nothing else
    EXPECT_NEAR(odo.lateral, truth.lateral, 1e-9) << i;
    EXPECT_NEAR(odo.heading, truth.heading, 1e-9) << i;
  }
  EXPECT_FALSE(d.odometry(5).has_value());
}

TEST(SimulatedOdometry, TheSeedDrawsTheNoise) {
  synth::OdometrySettings s;  // table 5.1's model
  const SimulatedOdometryDataset a(open_dataset(kExcerpt), s, 1), b(open_dataset(kExcerpt), s, 1),
      c(open_dataset(kExcerpt), s, 2);
  EXPECT_TRUE(a.odometry(4)->isApprox(*b.odometry(4)));
  EXPECT_FALSE(a.odometry(4)->isApprox(*c.odometry(4)));
}

TEST(SimulatedOdometry, ConfigErrorsNameTheKey) {
  const test::TempDir tmp;
  const auto parse = [&](const std::string& dataset) {
    const std::string text = "name: x\nkind: registration\ndataset: " + dataset + "\nmethods: [{name: a}]\n";
    return parse_experiment_config(YAML::Load(text), (tmp / "e99_x.yaml").string(), false);
  };
  EXPECT_THROW(parse("{source: synthetic, simulated_odometry: {model: thesis}}"), InputError);
  const ExperimentConfig bad_key =
      parse("{source: folder, path: " + kExcerpt.string() + ", simulated_odometry: {bias: 1}}");
  try {
    check_experiment_dataset(bad_key, "registration");
    ADD_FAILURE() << "an unknown odometry key is accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bias"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sextant
