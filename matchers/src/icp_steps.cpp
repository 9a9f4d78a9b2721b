#include "sextant/matchers/icp_steps.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

namespace sextant {

namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d S;
  S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return S;
}

/// Gauss–Newton information of the point-to-point residual ΔT·p − q for a left increment:
/// J = [I, −[p]×] (first order of eq. 3.8 at zero angles, R ≈ I + [ω]×).
Matrix6d point_to_point_information(const std::vector<Eigen::Vector3d>& input) {
  Matrix6d H = Matrix6d::Zero();
  Eigen::Matrix<double, 3, 6> J;
  J.leftCols<3>().setIdentity();
  for (const Eigen::Vector3d& p : input) {
    J.rightCols<3>() = -skew(p);
    H.noalias() += J.transpose() * J;
  }
  return H;
}

double mean_squared_distance(const Correspondences& pairs, const Eigen::Isometry3d& delta) {
  double sum = 0.0;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    sum += (delta * pairs.input[i] - pairs.reference[i]).squaredNorm();
  return sum / static_cast<double>(pairs.size());
}

double mean_squared_plane_distance(const Correspondences& pairs, const Eigen::Isometry3d& delta) {
  double sum = 0.0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const double r = pairs.normals[i].dot(delta * pairs.input[i] - pairs.reference[i]);
    sum += r * r;
  }
  return sum / static_cast<double>(pairs.size());
}

}  // namespace

IcpStep point_to_point_step(const Correspondences& pairs) {
  IcpStep step;
  const std::size_t n = pairs.size();
  if (n < 3 || pairs.reference.size() != n) {
    step.problem = "fewer than 3 point pairs";
    return step;
  }
  Eigen::Vector3d mean_p = Eigen::Vector3d::Zero(), mean_q = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    mean_p += pairs.input[i];
    mean_q += pairs.reference[i];
  }
  mean_p /= static_cast<double>(n);
  mean_q /= static_cast<double>(n);
  // Cross-covariance Σ (q − q̄)(p − p̄)ᵀ = U S Vᵀ; R = U·diag(1, 1, det(U Vᵀ))·Vᵀ (Arun et al. 1987).
  Eigen::Matrix3d W = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < n; ++i)
    W.noalias() += (pairs.reference[i] - mean_q) * (pairs.input[i] - mean_p).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(W, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d s = svd.singularValues();
  if (!s.allFinite() || !(s[0] > 0.0) || s[1] <= 1e-9 * s[0]) {
    step.problem = "point pairs are collinear or coincident: rotation not observable";
    return step;
  }
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  D(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  step.delta.linear() = svd.matrixU() * D * svd.matrixV().transpose();
  step.delta.translation() = mean_q - step.delta.linear() * mean_p;
  step.xi = to_pose6(step.delta).vector();
  step.H = point_to_point_information(pairs.input);
  step.score_before = mean_squared_distance(pairs, Eigen::Isometry3d::Identity());
  step.score_after = mean_squared_distance(pairs, step.delta);
  step.ok = step.delta.matrix().allFinite();
  if (!step.ok) step.problem = "non-finite increment";
  return step;
}

IcpStep point_to_plane_step(const Correspondences& pairs) {
  IcpStep step;
  const std::size_t n = pairs.size();
  if (n < 6 || pairs.reference.size() != n || pairs.normals.size() != n) {
    step.problem = "fewer than 6 point-plane pairs";
    return step;
  }
  // r = nᵀ(p − q) + nᵀΔt + (p × n)ᵀω, since nᵀ(ω × p) = ωᵀ(p × n).
  Matrix6d H = Matrix6d::Zero();
  Vector6d g = Vector6d::Zero();
  Vector6d J;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& p = pairs.input[i];
    const Eigen::Vector3d& normal = pairs.normals[i];
    J << normal, p.cross(normal);
    const double r = normal.dot(p - pairs.reference[i]);
    H.noalias() += J * J.transpose();
    g.noalias() += J * r;
  }
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eig(H);
  const Vector6d lambda = eig.eigenvalues();  // ascending
  if (!lambda.allFinite() || !(lambda[5] > 0.0) || lambda[0] <= 1e-10 * lambda[5]) {
    step.problem = "point-to-plane system is singular (too few independent normal directions)";
    return step;
  }
  // Gauss–Newton: H Δξ = −g.
  const Vector6d dx = eig.eigenvectors() * ((eig.eigenvectors().transpose() * -g).cwiseQuotient(lambda));
  step.xi = dx;
  step.delta = to_isometry(Pose6::from_vector(dx));  // eq. (3.8); first order equals I + [ω]×
  step.H = H;
  step.score_before = mean_squared_plane_distance(pairs, Eigen::Isometry3d::Identity());
  step.score_after = mean_squared_plane_distance(pairs, step.delta);
  step.ok = step.delta.matrix().allFinite();
  if (!step.ok) step.problem = "non-finite increment";
  return step;
}

}  // namespace sextant
