#include "sextant/posegraph/relative_pose_factor.hpp"

#include <ceres/autodiff_cost_function.h>
#include <ceres/rotation.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace sextant {
namespace {

/// r = L · [t(E); log(R(E))], E = T_ij*⁻¹ · T_i⁻¹ · T_j (see the header). Written once, for
/// doubles and for Ceres' Jets.
class RelativePoseResidual {
 public:
  RelativePoseResidual(const Eigen::Isometry3d& measured, const Matrix6d& sqrt_information)
      : t_m_(measured.translation()), q_m_(measured.rotation()), L_(sqrt_information) {}

  template <class T>
  bool operator()(const T* ti, const T* qi, const T* tj, const T* qj, T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> t_i(ti), t_j(tj);
    const Eigen::Map<const Eigen::Quaternion<T>> q_i(qi), q_j(qj);
    const Eigen::Quaternion<T> q_i_inv = q_i.conjugate();
    const Eigen::Quaternion<T> q_m_inv = q_m_.conjugate().template cast<T>();
    const Eigen::Quaternion<T> q_e = q_m_inv * (q_i_inv * q_j);                    // R(E)
    const Vec3 t_e = q_m_inv * (q_i_inv * (t_j - t_i) - t_m_.template cast<T>());  // t(E)
    const T q_wxyz[4] = {q_e.w(), q_e.x(), q_e.y(), q_e.z()};
    T log_r[3];
    ceres::QuaternionToAngleAxis(q_wxyz, log_r);  // SO(3) log map, angle in [0, π]
    Eigen::Matrix<T, 6, 1> e;
    e << t_e, log_r[0], log_r[1], log_r[2];
    Eigen::Map<Eigen::Matrix<T, 6, 1>> r(residual);
    r = L_.template cast<T>() * e;
    return true;
  }

 private:
  Eigen::Vector3d t_m_;
  Eigen::Quaterniond q_m_;
  Matrix6d L_;
};

}  // namespace

Vector6d relative_pose_error(const Eigen::Isometry3d& measured, const Eigen::Isometry3d& T_i,
                             const Eigen::Isometry3d& T_j) {
  const RelativePoseResidual f(measured, Matrix6d::Identity());
  const Eigen::Vector3d t_i = T_i.translation(), t_j = T_j.translation();
  const Eigen::Quaterniond q_i(T_i.rotation()), q_j(T_j.rotation());
  Vector6d e;
  f(t_i.data(), q_i.coeffs().data(), t_j.data(), q_j.coeffs().data(), e.data());
  return e;
}

ceres::CostFunction* make_relative_pose_cost(const Eigen::Isometry3d& measured,
                                             const Matrix6d& sqrt_information) {
  return new ceres::AutoDiffCostFunction<RelativePoseResidual, 6, 3, 4, 3, 4>(
      new RelativePoseResidual(measured, sqrt_information));
}

bool sqrt_information(const Matrix6d& information, Matrix6d* L) {
  if (!information.allFinite()) return false;
  const Matrix6d symmetric = 0.5 * (information + information.transpose());
  const Eigen::LLT<Matrix6d> llt(symmetric);
  if (llt.info() != Eigen::Success) return false;
  const Matrix6d U = llt.matrixU();
  if (!U.allFinite() || U.diagonal().minCoeff() <= 0.0) return false;
  *L = U;
  return true;
}

Matrix6d information_from_pose6_hessian(const Matrix6d& H, const Eigen::Isometry3d& measured) {
  const Vector6d xi = to_pose6(measured).vector();
  constexpr double h = 1e-6;
  Matrix6d J;
  for (int k = 0; k < 6; ++k) {
    Vector6d plus = xi, minus = xi;
    plus[k] += h;
    minus[k] -= h;
    const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
    J.col(k) = (relative_pose_error(measured, I, to_isometry(Pose6::from_vector(plus))) -
                relative_pose_error(measured, I, to_isometry(Pose6::from_vector(minus)))) /
               (2.0 * h);
  }
  const Matrix6d J_inv = J.fullPivLu().inverse();
  const Matrix6d omega = J_inv.transpose() * (0.5 * (H + H.transpose())) * J_inv;
  return 0.5 * (omega + omega.transpose());
}

}  // namespace sextant
