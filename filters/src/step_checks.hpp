#pragma once
// Input checks and a wall clock shared by the filter implementations (private to the module).
#include <chrono>
#include <vector>

#include <Eigen/Core>

#include "sextant/filters/covariance.hpp"
#include "sextant/filters/filter.hpp"
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

/// One observation z of a new landmark, with its noise R.
inline bool valid_observation(const SlamModel& model, const Eigen::VectorXd& z, const Eigen::MatrixXd& R) {
  return z.size() == model.observation_dim() && z.allFinite() && square_of(R, model.observation_dim());
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

/// The end of every moment-form step (EKF, sigma-point filters): wrap angles and renormalise
/// normals, optionally symmetrise P, and report a non-finite state or non-PD covariance.
inline StepStatus finish_moment_step(const SlamModel& model, Eigen::VectorXd& x, Eigen::MatrixXd& P,
                                     bool symmetrize, bool check_covariance) {
  normalize_state(model, x);
  if (symmetrize) P = symmetrized(P);
  if (!x.allFinite()) return StepStatus::kNotPositiveDefinite;
  if (check_covariance && !is_positive_definite(P)) return StepStatus::kNotPositiveDefinite;
  return StepStatus::kOk;
}

}  // namespace sextant::detail
