#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/filters/fastslam.hpp"
#include "sextant/filters/filter.hpp"
#include "sextant/filters/filter_spec.hpp"
#include "sextant/filters/range_bearing_model.hpp"
#include "sextant/filters/yaml.hpp"

namespace sextant {
namespace {

TEST(FilterSpec, TheCatalogueKnowsEveryFilterOnce) {
  auto model = std::make_shared<RangeBearingModel>();
  EXPECT_EQ(filter_names(),
            (std::vector<std::string>{"ckf", "eif", "ekf", "eseif", "fastslam2", "rspkf", "seif", "ukf"}));
  for (const std::string& name : filter_names()) {
    ASSERT_TRUE(default_filter_spec(name)) << name;
    EXPECT_EQ(default_filter_spec(name)->name(), name);
    EXPECT_EQ(make_filter(name, model)->name(), name);
    EXPECT_EQ(default_filter(name)(model)->name(), name);
  }
  EXPECT_FALSE(default_filter_spec("pf"));
  EXPECT_FALSE(default_filter("pf"));
  EXPECT_THROW(make_filter("pf", model), InputError);  // names the file and the known filters
  EXPECT_EQ(FilterSpec().name(), "ekf");
}

TEST(FilterSpec, AFilterReadFromYamlIsTheStructsFilter) {
  auto model = std::make_shared<RangeBearingModel>();
  UkfSettings ukf;
  ukf.unscented.alpha = 0.5;
  ukf.unscented.kappa_three_minus_n = true;
  const FilterSpec read =
      read_filter_spec("ukf", YAML::Load("{alpha: 0.5, kappa_three_minus_n: true}"), "f.yaml");
  ASSERT_NE(read.get<UkfSettings>(), nullptr);
  EXPECT_EQ(make_filter(read, model)->approximation(), make_filter(ukf, model)->approximation());
  EXPECT_NE(make_filter(read, model)->approximation(), make_filter(UkfSettings{}, model)->approximation());
  // A seed is given or left to the run (RSPKF: each Monte Carlo repetition its own).
  EXPECT_FALSE(read_filter_spec("rspkf", YAML::Node(), "f.yaml").get<RspkfSettings>()->seed);
  EXPECT_EQ(*read_filter_spec("rspkf", YAML::Load("{seed: 9}"), "f.yaml").get<RspkfSettings>()->seed, 9u);
}

TEST(FilterSpec, InvalidSettingsAndAPriorThatDoesNotFitTheModelAreErrors) {
  auto model = std::make_shared<RangeBearingModel>();  // a 3-entry pose
  RspkfSettings bad;
  bad.integration.iterations = 0;
  EXPECT_THROW(make_filter(bad, model), std::invalid_argument);
  EXPECT_THROW(filter_factory(bad), std::invalid_argument);
  const YAML::Node six = YAML::Load("{relocation_prior: [1, 1, 1, 1, 1, 1]}");
  EXPECT_THROW(read_filter_spec("eseif", six, "f.yaml", model->pose_dim()), InputError);
  EXPECT_THROW(make_filter("eseif", model, six, "f.yaml"), InputError);
  const FilterSpec unchecked = read_filter_spec("eseif", six, "f.yaml");  // no model: checked when built
  EXPECT_THROW(make_filter(unchecked, model), std::invalid_argument);
  EXPECT_EQ(make_filter("eseif", model, YAML::Load("{relocation_prior: [1, 1, 1]}"), "f.yaml")->name(),
            "eseif");
}

TEST(FilterRegistry, SettingsErrorsNameTheKey) {
  auto model = std::make_shared<RangeBearingModel>();
  try {
    make_filter("ukf", model, YAML::Load("alpha: 0.5\nalhpa: 1"), "f.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("alhpa"), std::string::npos) << e.what();
  }
  EXPECT_THROW(make_filter("rspkf", model, YAML::Load("iterations: 0"), "f.yaml"), InputError);
  EXPECT_THROW(make_filter("seif", model, YAML::Load("mean_recovery: magic"), "f.yaml"), InputError);
  EXPECT_THROW(make_filter("ekf", model, YAML::Load("joseph_form: maybe"), "f.yaml"), InputError);
  EXPECT_THROW(make_filter("fastslam2", model, YAML::Load("particles: 0"), "f.yaml"), InputError);
  EXPECT_THROW(make_filter("fastslam2", model, YAML::Load("resample_threshold: 2"), "f.yaml"), InputError);
  auto f = make_filter("fastslam2", model, YAML::Load("{particles: 7, seed: 3}"), "f.yaml");
  auto* particles = dynamic_cast<FastSlam*>(f.get());
  ASSERT_NE(particles, nullptr);
  ASSERT_TRUE(particles->initialize(Eigen::VectorXd::Zero(3), Eigen::MatrixXd::Identity(3, 3)).ok());
  EXPECT_EQ(particles->particles().size(), 7u);
}

TEST(Filters, BadInputIsAStatusNotACrash) {
  auto model = std::make_shared<RangeBearingModel>();
  for (const std::string name : {"ekf", "ukf", "seif"}) {
    auto f = make_filter(name, model);
    f->initialize(Eigen::VectorXd::Zero(3), Eigen::MatrixXd::Identity(3, 3));
    const Eigen::Vector2d nan_u(std::nan(""), 0.0);
    EXPECT_EQ(f->predict(nan_u, Eigen::Matrix2d::Identity()).status, StepStatus::kInvalidInput);
    EXPECT_EQ(f->update({Eigen::Vector2d(1, 0)}, Eigen::Matrix2d::Identity(), {3}).status,
              StepStatus::kInvalidInput);
    EXPECT_EQ(f->initialize(Eigen::VectorXd::Zero(3), -Eigen::MatrixXd::Identity(3, 3)).ok(), false);
    EXPECT_GE(f->summary().failures(), 3u);
  }
}

}  // namespace
}  // namespace sextant
