#pragma once
// Input checks and a wall clock shared by the filter implementations (private to the module).
#include <chrono>
#include <vector>

#include <Eigen/Core>

#include "sextant/filters/slam_model.hpp"

namespace sextant::detail {

class StepClock {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

inline bool square_of(const Eigen::MatrixXd& M, Eigen::Index n) {
  return M.rows() == n && M.cols() == n && M.allFinite();
}

inline bool valid_state(const SlamModel& model, const Eigen::VectorXd& x0, const Eigen::MatrixXd& P0) {
  const Eigen::Index extra = x0.size() - model.pose_dim();
  return extra >= 0 && extra % model.landmark_dim() == 0 && x0.allFinite() && square_of(P0, x0.size());
}

inline bool valid_control(const SlamModel& model, const Eigen::VectorXd& u, const Eigen::MatrixXd& Q) {
  return u.size() == model.control_dim() && u.allFinite() && square_of(Q, model.control_dim());
}

inline bool valid_observations(const SlamModel& model, int landmarks, const std::vector<Eigen::VectorXd>& zs,
                               const Eigen::MatrixXd& R, const std::vector<int>& associations) {
  if (zs.size() != associations.size() || !square_of(R, model.observation_dim())) return false;
  for (std::size_t i = 0; i < zs.size(); ++i) {
    if (zs[i].size() != model.observation_dim() || !zs[i].allFinite()) return false;
    if (associations[i] < 0 || associations[i] >= landmarks) return false;
  }
  return true;
}

}  // namespace sextant::detail
