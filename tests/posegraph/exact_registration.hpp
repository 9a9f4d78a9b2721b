#pragma once
// A stand-in for the verifying registration of loop closing (loop_closing.hpp), for the posegraph
// tests: it finds the true relative pose with a confident Hessian.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sextant/core/pose.hpp"
#include "sextant/posegraph/loop_closing.hpp"

namespace sextant::test {

/// A registration that finds the true relative pose truth[i]⁻¹·truth[j], trusted (or, with
/// `trusted` false, suspect), with a confident Hessian.
inline ClosureRegistration exact_registration(const std::vector<Eigen::Isometry3d>& truth,
                                              bool trusted = true) {
  return [truth, trusted](std::size_t i, std::size_t j, const Eigen::Isometry3d&, std::uint64_t) {
    RegistrationResult r;
    r.T = relative(truth[i], truth[j]);
    r.converged = true;
    r.why = Termination::kConverged;
    r.H = Matrix6d::Identity() * 1e4;
    r.score = 1000.0;
    r.matched_points = r.input_points = 1000;
    r.quality.assessed = true;
    r.quality.trust = trusted ? Trust::kOk : Trust::kSuspect;
    r.quality.reason = trusted ? "" : "made up";
    return r;
  };
}

}  // namespace sextant::test
