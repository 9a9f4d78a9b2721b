#include "sextant/filters/innovation_gate.hpp"

#include <Eigen/Cholesky>

#include <limits>

namespace sextant {

double innovation_distance(const Filter& filter, const Eigen::VectorXd& z, const Eigen::MatrixXd& R,
                           int landmark) {
  constexpr double kFar = std::numeric_limits<double>::infinity();
  const SlamModel& model = filter.model();
  const int p = model.pose_dim(), l = model.landmark_dim();
  const Eigen::VectorXd x = filter.mean();
  const Eigen::VectorXd pose = x.head(p);
  const Eigen::VectorXd m = x.segment(landmark_offset(model, landmark), l);
  const Eigen::VectorXd predicted = model.observe(pose, m);
  Eigen::VectorXd nu = model.align_observation(z, predicted) - predicted;
  wrap_entries(nu, model.observation_angles());
  Eigen::MatrixXd H(model.observation_dim(), p + l);
  H << model.observe_jacobian_pose(pose, m), model.observe_jacobian_landmark(pose, m);
  const Eigen::MatrixXd S = H * filter.joint_covariance({landmark}) * H.transpose() + R;
  if (!nu.allFinite() || !S.allFinite()) return kFar;
  const Eigen::LLT<Eigen::MatrixXd> llt(0.5 * (S + S.transpose()));
  if (llt.info() != Eigen::Success) return kFar;
  return nu.dot(llt.solve(nu));
}

}  // namespace sextant
