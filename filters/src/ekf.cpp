#include <Eigen/Cholesky>

#include "sextant/filters/covariance.hpp"
#include "sextant/filters/gaussian_filters.hpp"
#include "step_checks.hpp"

namespace sextant {

Ekf::Ekf(std::shared_ptr<const SlamModel> model, GaussianFilterSettings settings)
    : MomentFilter(std::move(model), settings) {}

// eqs. (4.62)–(4.63): only the pose rows and columns of P change, O(n). P⁺ = J P Jᵀ + diag(GQGᵀ, 0)
// with J = diag(F, I): P⁺ is positive definite when P is and F is regular, so the check is of
// the new pose block only.
StepResult Ekf::predict(const Eigen::VectorXd& u, const Eigen::MatrixXd& Q) {
  detail::StepClock clock;
  if (!detail::valid_control(*model_, u, Q)) return record(StepStatus::kInvalidInput, clock.seconds());
  const int p = model_->pose_dim();
  const Eigen::Index n = x_.size();
  const Eigen::VectorXd pose = x_.head(p);
  const Eigen::MatrixXd F = model_->process_jacobian_pose(pose, u);
  const Eigen::MatrixXd G = model_->process_jacobian_control(pose, u);
  x_.head(p) = model_->process(pose, u);
  const Eigen::MatrixXd Pvv = F * P_.topLeftCorner(p, p) * F.transpose() + G * Q * G.transpose();
  if (n > p) {
    const Eigen::MatrixXd PvL = F * P_.topRightCorner(p, n - p);
    P_.topRightCorner(p, n - p) = PvL;
    P_.bottomLeftCorner(n - p, p) = PvL.transpose();
  }
  P_.topLeftCorner(p, p) = symmetrized(Pvv);
  const Eigen::MatrixXd pose_block = P_.topLeftCorner(p, p);
  return record(finish_step(false, &pose_block), clock.seconds());  // P stays symmetric: O(n)
}

// eqs. (4.65)–(4.66) with stacked observations; P Hᵀ is formed from the pose and landmark
// columns only, so the cost is O(n·m) plus the O(n²·m) covariance downdate.
StepResult Ekf::update(const std::vector<Eigen::VectorXd>& zs, const Eigen::MatrixXd& R,
                       const std::vector<int>& associations) {
  detail::StepClock clock;
  if (!detail::valid_observations(*model_, num_landmarks(), zs, R, associations))
    return record(StepStatus::kInvalidInput, clock.seconds());
  if (zs.empty()) return record(StepStatus::kOk, clock.seconds());
  const int p = model_->pose_dim(), l = model_->landmark_dim(), od = model_->observation_dim();
  const int count = static_cast<int>(zs.size());
  const Eigen::Index n = x_.size(), m = static_cast<Eigen::Index>(count) * od;
  const Eigen::VectorXd pose = x_.head(p);

  Eigen::VectorXd innovation(m);
  std::vector<Eigen::MatrixXd> Hp(count), Hl(count);
  Eigen::MatrixXd PHt(n, m);
  for (int j = 0; j < count; ++j) {
    const Eigen::Index off = landmark_offset(*model_, associations[j]);
    const Eigen::VectorXd landmark = x_.segment(off, l);
    const Eigen::VectorXd predicted = model_->observe(pose, landmark);
    Eigen::VectorXd nu = model_->align_observation(zs[j], predicted) - predicted;
    wrap_entries(nu, model_->observation_angles());
    innovation.segment(j * od, od) = nu;
    Hp[j] = model_->observe_jacobian_pose(pose, landmark);
    Hl[j] = model_->observe_jacobian_landmark(pose, landmark);
    PHt.middleCols(j * od, od) =
        P_.leftCols(p) * Hp[j].transpose() + P_.middleCols(off, l) * Hl[j].transpose();
  }
  Eigen::MatrixXd S = block_diagonal(R, count);
  for (int j = 0; j < count; ++j) {
    const Eigen::Index off = landmark_offset(*model_, associations[j]);
    S.middleRows(j * od, od) += Hp[j] * PHt.topRows(p) + Hl[j] * PHt.middleRows(off, l);
  }
  Eigen::LLT<Eigen::MatrixXd> llt(symmetrized(S));
  if (llt.info() != Eigen::Success) return record(StepStatus::kSingularInnovation, clock.seconds());
  const Eigen::MatrixXd K = llt.solve(PHt.transpose()).transpose();  // K = P Hᵀ S⁻¹
  x_ += K * innovation;
  if (s_.joseph_form) {
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(m, n);
    for (int j = 0; j < count; ++j) {
      H.block(j * od, 0, od, p) = Hp[j];
      H.block(j * od, landmark_offset(*model_, associations[j]), od, l) += Hl[j];
    }
    Eigen::MatrixXd IKH = -K * H;
    IKH.diagonal().array() += 1.0;
    P_ = IKH * P_ * IKH.transpose() + K * block_diagonal(R, count) * K.transpose();
  } else {
    P_.noalias() -= K * PHt.transpose();  // P − K S Kᵀ
  }
  return record(finish_step(), clock.seconds());
}

// eqs. (4.67)–(4.68). The new landmark's Schur complement in P⁺ is Gz R Gzᵀ: P⁺ is positive
// definite when P is and Gz R Gzᵀ is, so that block is what the step checks (O(n²) in all).
StepResult Ekf::augment(const Eigen::VectorXd& z, const Eigen::MatrixXd& R) {
  detail::StepClock clock;
  if (!detail::valid_observation(*model_, z, R)) return record(StepStatus::kInvalidInput, clock.seconds());
  const int p = model_->pose_dim(), l = model_->landmark_dim();
  const Eigen::Index n = x_.size();
  const Eigen::VectorXd pose = x_.head(p);
  const Eigen::MatrixXd Gv = model_->augment_jacobian_pose(pose, z);
  const Eigen::MatrixXd Gz = model_->augment_jacobian_observation(pose, z);
  const Eigen::MatrixXd Pmx = Gv * P_.topRows(p);  // [P_mv P_mL]
  const Eigen::MatrixXd Pmm = Gv * P_.topLeftCorner(p, p) * Gv.transpose() + Gz * R * Gz.transpose();
  x_.conservativeResize(n + l);
  x_.tail(l) = model_->augment(pose, z);
  P_.conservativeResize(n + l, n + l);
  P_.bottomLeftCorner(l, n) = Pmx;
  P_.topRightCorner(n, l) = Pmx.transpose();
  P_.bottomRightCorner(l, l) = Pmm;
  const Eigen::MatrixXd schur = Gz * R * Gz.transpose();
  return record(finish_step(true, &schur), clock.seconds());
}

}  // namespace sextant
