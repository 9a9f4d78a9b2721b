#include "sextant/filters/gaussian_filters.hpp"

#include "sextant/core/checked_settings.hpp"
#include "step_checks.hpp"

namespace sextant {

bool GaussianFilterSettings::valid(std::string* /*why*/) const {
  return true;
}

MomentFilter::MomentFilter(std::shared_ptr<const SlamModel> model, GaussianFilterSettings settings)
    : model_(std::move(model)),
      s_(checked(settings, "Gaussian filter")),
      x_(Eigen::VectorXd::Zero(model_->pose_dim())),
      P_(Eigen::MatrixXd::Identity(model_->pose_dim(), model_->pose_dim())) {}

int MomentFilter::num_landmarks() const {
  return landmark_count(*model_, x_.size());
}

StepStatus MomentFilter::finish_step(bool symmetrize, const Eigen::MatrixXd* changed_block) {
  const StepStatus status = detail::finish_moment_step(*model_, x_, P_, s_.symmetrize && symmetrize,
                                                       s_.check_covariance && changed_block == nullptr);
  if (status == StepStatus::kOk && s_.check_covariance && changed_block != nullptr &&
      !is_positive_definite(*changed_block))
    return StepStatus::kNotPositiveDefinite;
  return status;
}

StepResult MomentFilter::initialize(const Eigen::VectorXd& x0, const Eigen::MatrixXd& P0) {
  detail::StepClock clock;
  if (!detail::valid_state(*model_, x0, P0)) return record(StepStatus::kInvalidInput, clock.seconds());
  x_ = x0;
  P_ = P0;
  return record(finish_step(), clock.seconds());
}

}  // namespace sextant
