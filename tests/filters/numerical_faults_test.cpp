// Numerical faults injected into the filters (issue 13): a measurement noise that is not positive
// definite, a singular innovation, NaN in a measurement or in the control. Each is a StepStatus
// in the step's result and counted in the summary; the state stays finite, nothing aborts.
// (NaN control, negative P0: Filters.BadInputIsAStatusNotACrash; UKF losing positive
// definiteness: RangeBearing.UkfLosesPositiveDefinitenessWhenP0IsScaledUp.)
#include <gtest/gtest.h>

#include <cmath>

#include "sextant/filters/filter.hpp"
#include "sextant/filters/range_bearing_model.hpp"
#include "sextant/filters/yaml.hpp"

namespace sextant {
namespace {

std::unique_ptr<Filter> filter_with_one_landmark(const std::string& name) {
  auto f = make_filter(name, std::make_shared<RangeBearingModel>());
  Eigen::VectorXd x0(5);
  x0 << 0, 0, 0, 5, 1;
  Eigen::MatrixXd P0 = 0.1 * Eigen::MatrixXd::Identity(5, 5);
  EXPECT_TRUE(f->initialize(x0, P0).ok()) << name;
  return f;
}

class FilterNumericalFaults : public ::testing::TestWithParam<const char*> {};

TEST_P(FilterNumericalFaults, EachFaultIsAStatusAndTheStateStaysFinite) {
  const std::string name = GetParam();
  const Eigen::Vector2d z(std::hypot(5.0, 1.0), std::atan2(1.0, 5.0));

  auto f = filter_with_one_landmark(name);
  const Eigen::Vector2d nan_z(std::nan(""), 0.1);
  EXPECT_EQ(f->update({nan_z}, Eigen::Matrix2d::Identity() * 0.01, {0}).status, StepStatus::kInvalidInput)
      << name;
  EXPECT_TRUE(f->mean().allFinite()) << name;

  // R not positive definite (negative variances): refused or reported, never a NaN state.
  const StepResult bad_r = f->update({z}, -Eigen::Matrix2d::Identity(), {0});
  EXPECT_NE(bad_r.status, StepStatus::kOk) << name;
  EXPECT_TRUE(f->mean().allFinite()) << name;
  EXPECT_TRUE(f->covariance().allFinite()) << name;

  // Singular innovation: zero measurement noise on a landmark known exactly in a zero-covariance state.
  auto g = make_filter(name, std::make_shared<RangeBearingModel>());
  Eigen::VectorXd x0(5);
  x0 << 0, 0, 0, 5, 1;
  const StepResult init = g->initialize(x0, Eigen::MatrixXd::Zero(5, 5));
  if (init.ok()) {
    const StepResult singular = g->update({z}, Eigen::Matrix2d::Zero(), {0});
    EXPECT_NE(singular.status, StepStatus::kOk) << name;
    EXPECT_TRUE(g->mean().allFinite()) << name;
  } else {
    EXPECT_NE(init.status, StepStatus::kOk) << name;  // a zero covariance refused up front
  }
  EXPECT_GE(f->summary().failures() + g->summary().failures(), 2u) << name;
}

// The EKF checks only the block its predict and augment add (P stays positive definite exactly
// when that block is): a negative Q or R must still be reported there.
TEST(EkfBlockChecks, NegativeProcessOrObservationNoiseIsReported) {
  auto f = filter_with_one_landmark("ekf");
  const Eigen::Vector2d u(0.1, 0.0);
  EXPECT_EQ(f->predict(u, -100.0 * Eigen::Matrix2d::Identity()).status, StepStatus::kNotPositiveDefinite);
  auto g = filter_with_one_landmark("ekf");
  EXPECT_TRUE(g->predict(u, 0.01 * Eigen::Matrix2d::Identity()).ok());
  const Eigen::Vector2d z(3.0, 0.5);
  EXPECT_EQ(g->augment(z, -Eigen::Matrix2d::Identity()).status, StepStatus::kNotPositiveDefinite);
  auto h = filter_with_one_landmark("ekf");
  EXPECT_TRUE(h->augment(z, 0.01 * Eigen::Matrix2d::Identity()).ok());
  EXPECT_EQ(h->num_landmarks(), 2);
}

INSTANTIATE_TEST_SUITE_P(EveryFilter, FilterNumericalFaults,
                         ::testing::Values("ekf", "ukf", "ckf", "rspkf", "seif", "eif", "eseif"));

}  // namespace
}  // namespace sextant
