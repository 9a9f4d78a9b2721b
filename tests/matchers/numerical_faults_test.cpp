// Numerical faults injected into the matchers (issue 13): NaN points in the clouds and a singular
// Hessian (every input point identical). The result reports it (converged = false with a reason,
// or the NaN points left out); never a NaN pose, never an abort. NaN initial guesses, empty and
// degenerate clouds are Registration.DegenerateInputNeverCrashes in registration_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/SVD>

#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/yaml.hpp"
#include "test_clouds.hpp"

namespace sextant {
namespace {

bool finite_pose(const Eigen::Isometry3d& T) {
  return T.matrix().allFinite();
}

TEST(MatcherNumericalFaults, NaNPointsInTheCloudsNeverGiveANaNResult) {
  Rng rng(5);
  PointCloud reference = test::yard(rng);
  PointCloud input = reference;
  const float nan = std::nanf("");
  for (std::size_t i = 0; i < input.size(); i += 7)
    input.mutable_points()[i] = Eigen::Vector3f(nan, 0.0f, nan);
  for (std::size_t i = 0; i < reference.size(); i += 11) reference.mutable_points()[i].y() = nan;
  for (const char* method : {"ndt", "mlndt", "icp_p2p", "icp_p2l"}) {
    auto m = make_matcher(method, YAML::Node());
    m->set_reference(reference);
    const RegistrationResult r = m->align(input, Eigen::Isometry3d::Identity());
    EXPECT_TRUE(finite_pose(r.T)) << method << ": " << r.summary();
    EXPECT_TRUE(r.H.allFinite()) << method << ": " << r.summary();
    EXPECT_TRUE(std::isfinite(r.score)) << method << ": " << r.summary();
    if (!r.converged) {
      EXPECT_NE(r.why, Termination::kConverged) << method;
    }
  }
}

TEST(MatcherNumericalFaults, SingularHessianIsReportedNotInverted) {
  Rng rng(6);
  const PointCloud reference = test::yard(rng);
  PointCloud same_point;  // 500 copies of one point: the Hessian of every pose parameter is singular
  for (int i = 0; i < 500; ++i) same_point.push_back(Eigen::Vector3f(1.0f, 2.0f, 0.5f));
  for (const char* method : {"ndt", "mlndt", "icp_p2p", "icp_p2l"}) {
    for (const char* solver : {"newton", "lm"}) {
      if (std::string(method).rfind("icp", 0) == 0 && std::string(solver) == "lm") continue;
      const YAML::Node settings = std::string(method).rfind("icp", 0) == 0
                                      ? YAML::Node()
                                      : YAML::Load(std::string("{solver: ") + solver + "}");
      auto m = make_matcher(method, settings);
      m->set_reference(reference);
      const RegistrationResult r = m->align(same_point, Eigen::Isometry3d::Identity());
      EXPECT_TRUE(finite_pose(r.T)) << method << " " << solver << ": " << r.summary();
      EXPECT_TRUE(r.H.allFinite()) << method << " " << solver << ": " << r.summary();
      EXPECT_FALSE(r.summary().empty());
      // Not a silent success: not converged with a reason, or converged with a Hessian that is
      // either regular (NDT's second-order terms can make it so) or flagged as singular.
      const Eigen::JacobiSVD<Matrix6d> svd(r.H);
      const bool deficient = svd.singularValues()(5) <= 1e-9 * svd.singularValues()(0);
      if (r.converged && deficient) {
        EXPECT_NE(r.summary().find("Hessian singular"), std::string::npos)
            << method << " " << solver << ": " << r.summary();
      }
    }
  }
}

TEST(MatcherNumericalFaults, ASingularHessianIsNamedInTheSummary) {
  RegistrationResult r;
  r.converged = true;
  r.why = Termination::kConverged;
  r.H = Matrix6d::Ones();  // rank 1: five directions unconstrained
  EXPECT_NE(r.summary().find("Hessian singular (5 unconstrained direction(s))"), std::string::npos)
      << r.summary();
  r.H = Matrix6d::Zero();  // a 3-DOF matcher leaves the other rows at zero: not singular
  r.H.diagonal() << 2, 3, 0, 0, 0, 4;
  EXPECT_EQ(r.summary().find("Hessian singular"), std::string::npos) << r.summary();
}

}  // namespace
}  // namespace sextant
