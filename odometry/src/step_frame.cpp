#include "step_frame.hpp"

namespace sextant::odometry_detail {

StepFrame::StepFrame(const PointCloud& reference, const PointCloud& input)
    : reference_(reference), input_(input), frame_(registration_centre(reference)) {
  if (!frame_.moved()) return;
  local_reference_ = frame_.cloud(reference);
  local_input_ = frame_.cloud(input);
}

std::vector<Eigen::Isometry3d> StepFrame::local(std::vector<Eigen::Isometry3d> transforms) const {
  for (Eigen::Isometry3d& T : transforms) T = frame_.local(T);
  return transforms;
}

void StepFrame::to_coordinates(OdometryStep& step) const {
  if (!frame_.moved()) return;
  step.relative = frame_.coordinates(step.relative);
  step.guess = frame_.coordinates(step.guess);
  step.first_relative = frame_.coordinates(step.first_relative);
  step.hessian = frame_.hessian_in_coordinates(step.hessian, step.relative);
}

}  // namespace sextant::odometry_detail
