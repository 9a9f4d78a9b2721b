#include "sextant/filters/filter.hpp"

#include <stdexcept>

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

FilterDiagnostics Filter::diagnostics() const {
  return {};
}

std::string Filter::approximation() const {
  return "linearised (Jacobians, eqs. 4.62-4.68): no sigma points";
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

Eigen::MatrixXd joint_block(const SlamModel& model, const Eigen::MatrixXd& P,
                            const std::vector<int>& landmarks) {
  const int count = landmark_count(model, P.rows());
  std::vector<Eigen::Index> rows;
  for (int k = 0; k < model.pose_dim(); ++k) rows.push_back(k);
  for (int j : landmarks) {
    if (j < 0 || j >= count) throw std::out_of_range("joint_covariance: no landmark " + std::to_string(j));
    for (int k = 0; k < model.landmark_dim(); ++k) rows.push_back(landmark_offset(model, j) + k);
  }
  return P(rows, rows);
}

Eigen::MatrixXd Filter::joint_covariance(const std::vector<int>& landmarks) const {
  return joint_block(model(), covariance(), landmarks);
}

StepResult Filter::record(StepStatus status, double seconds) {
  summary_.add(status);
  return StepResult{status, seconds};
}

}  // namespace sextant
