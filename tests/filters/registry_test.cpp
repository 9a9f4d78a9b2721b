#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/filters/fastslam.hpp"
#include "sextant/filters/filter.hpp"
#include "sextant/filters/range_bearing_model.hpp"
#include "sextant/filters/yaml.hpp"

namespace sextant {
namespace {

TEST(FilterRegistry, KnowsEveryFilter) {
  auto model = std::make_shared<RangeBearingModel>();
  for (const std::string name : {"ekf", "ukf", "ckf", "rspkf", "seif", "eif", "eseif", "fastslam2"}) {
    ASSERT_TRUE(filter_registry().contains(name)) << name;
    EXPECT_EQ(make_filter(name, model)->name(), name);
  }
  EXPECT_THROW(make_filter("pf", model), std::invalid_argument);
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
