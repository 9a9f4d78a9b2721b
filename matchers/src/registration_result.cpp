#include "sextant/matchers/registration_result.hpp"

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
  }
  return "unknown";
}

std::string RegistrationResult::summary() const {
  return fmt::format("{} after {} iterations ({}), score {:.6g}, {} of {} points matched, {:.4f} s{}",
                     converged ? "converged" : "not converged", iterations, to_string(why), score,
                     matched_points, input_points, seconds,
                     fallback.empty() ? "" : "; fallback: " + fallback);
}

RegistrationResult not_started(Termination why, std::size_t input_points, const Eigen::Isometry3d& initial) {
  RegistrationResult r;
  r.why = why;
  r.input_points = input_points;
  if (is_finite(initial)) r.T = initial;
  return r;
}

}  // namespace sextant
