#include "sextant/matchers/registration_result.hpp"

#include <vector>

#include <Eigen/Eigenvalues>

#include <fmt/format.h>

namespace sextant {

std::string to_string(Termination why) {
  switch (why) {
    case Termination::kConverged: return "converged";
    case Termination::kMaxIterations: return "max_iterations";
    case Termination::kTooFewCorrespondences: return "too_few_correspondences";
    case Termination::kNonFiniteInput: return "non_finite_input";
    case Termination::kEmptyInput: return "empty_input";
    case Termination::kSolverFailure: return "solver_failure";
    case Termination::kDiverged: return "diverged";
    case Termination::kGridTooLarge: return "grid_too_large";
    case Termination::kNoGaussians: return "no_gaussians";
  }
  return "unknown";
}

namespace {

/// Rank deficit of the symmetric part of H over its active parameters (rows that are not all
/// zero: a matcher restricted to fewer degrees of freedom leaves the others' rows at zero).
int hessian_deficit(const Matrix6d& H) {
  if (!H.allFinite()) return 0;
  std::vector<int> active;
  for (int i = 0; i < 6; ++i) {
    if (!H.row(i).isZero(0.0)) active.push_back(i);
  }
  if (active.empty()) return 0;
  const int n = static_cast<int>(active.size());
  Eigen::MatrixXd S(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) S(i, j) = 0.5 * (H(active[i], active[j]) + H(active[j], active[i]));
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(S, Eigen::EigenvaluesOnly);
  const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
  return n - static_cast<int>((eig.eigenvalues().array().abs() > 1e-9 * largest).count());
}

}  // namespace

std::string RegistrationResult::summary() const {
  std::string text =
      fmt::format("{} after {} iterations ({}), score {:.6g}, {} of {} points matched, {:.4f} s",
                  converged ? "converged" : "not converged", iterations, to_string(why), score,
                  matched_points, input_points, seconds);
  // A singular Hessian (e.g. every point identical, a single plane for a 6-DOF problem): the pose is
  // finite but some directions are unconstrained and the covariance H⁻¹ (eq. 3.50) does not exist.
  const int deficit = hessian_deficit(H);
  if (converged && deficit > 0) {
    text += fmt::format(", Hessian singular ({} unconstrained direction(s)): covariance undefined", deficit);
  }
  if (!fallback.empty()) text += "; fallback: " + fallback;
  return text;
}

RegistrationResult not_started(Termination why, std::size_t input_points, const Eigen::Isometry3d& initial) {
  RegistrationResult r;
  r.why = why;
  r.input_points = input_points;
  if (is_finite(initial)) r.T = initial;
  return r;
}

}  // namespace sextant
