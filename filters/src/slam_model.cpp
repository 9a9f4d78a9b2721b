#include "sextant/filters/slam_model.hpp"

#include "sextant/core/pose.hpp"

namespace sextant {

int landmark_count(const SlamModel& model, Eigen::Index state_size) {
  return static_cast<int>((state_size - model.pose_dim()) / model.landmark_dim());
}

Eigen::Index landmark_offset(const SlamModel& model, int index) {
  return model.pose_dim() + static_cast<Eigen::Index>(index) * model.landmark_dim();
}

void wrap_entries(Eigen::Ref<Eigen::VectorXd> v, const std::vector<int>& angles, Eigen::Index offset) {
  for (int i : angles) v[offset + i] = wrap_angle(v[offset + i]);
}

Eigen::VectorXd state_difference(const SlamModel& model, const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  Eigen::VectorXd d = a - b;
  wrap_entries(d, model.pose_angles());
  return d;
}

void normalize_state(const SlamModel& model, Eigen::Ref<Eigen::VectorXd> x) {
  wrap_entries(x, model.pose_angles());
  const int n = landmark_count(model, x.size());
  for (int i = 0; i < n; ++i)
    model.normalize_landmark(x.segment(landmark_offset(model, i), model.landmark_dim()));
}

}  // namespace sextant
