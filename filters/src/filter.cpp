#include "sextant/filters/filter.hpp"

namespace sextant {

std::string to_string(StepStatus status) {
  switch (status) {
    case StepStatus::kOk: return "ok";
    case StepStatus::kNotPositiveDefinite: return "covariance not positive definite";
    case StepStatus::kCholeskyFailed: return "Cholesky factorisation failed";
    case StepStatus::kSingularInnovation: return "singular innovation covariance";
    case StepStatus::kInvalidInput: return "invalid input";
  }
  return "unknown";
}

void FilterSummary::add(StepStatus status) {
  ++steps;
  switch (status) {
    case StepStatus::kOk: break;
    case StepStatus::kNotPositiveDefinite: ++not_positive_definite; break;
    case StepStatus::kCholeskyFailed: ++cholesky_failures; break;
    case StepStatus::kSingularInnovation: ++singular_innovations; break;
    case StepStatus::kInvalidInput: ++invalid_inputs; break;
  }
}

StepResult Filter::record(StepStatus status, double seconds) {
  summary_.add(status);
  return StepResult{status, seconds};
}

}  // namespace sextant
