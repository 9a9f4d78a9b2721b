#include "icp/icp_steps.hpp"

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

/// Solves H·Δξ = −g over the free parameters of `dof` (the others stay 0). False when the
/// reduced system is singular or not finite.
bool solve_free_parameters(const Matrix6d& H, const Vector6d& g, const DofMask& dof, Vector6d* dx) {
  std::vector<int> free;
  for (int i = 0; i < 6; ++i)
    if (dof.active[static_cast<std::size_t>(i)]) free.push_back(i);
  const int n = static_cast<int>(free.size());
  Eigen::MatrixXd Hr(n, n);
  Eigen::VectorXd gr(n);
  for (int a = 0; a < n; ++a) {
    gr[a] = g[free[a]];
    for (int b = 0; b < n; ++b) Hr(a, b) = H(free[a], free[b]);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Hr);
  const Eigen::VectorXd lambda = eig.eigenvalues();  // ascending
  if (n == 0 || !lambda.allFinite() || !(lambda[n - 1] > 0.0) || lambda[0] <= 1e-10 * lambda[n - 1])
    return false;
  const Eigen::VectorXd xr =
      eig.eigenvectors() * ((eig.eigenvectors().transpose() * -gr).cwiseQuotient(lambda));
  dx->setZero();
  for (int a = 0; a < n; ++a) (*dx)[free[a]] = xr[a];
  return dx->allFinite();
}

/// One Gauss–Newton step of the point-to-point residual over the free parameters.
IcpStep linearised_point_to_point_step(const Correspondences& pairs, const DofMask& dof) {
  IcpStep step;
  Vector6d g = Vector6d::Zero();
  Eigen::Matrix<double, 3, 6> J;
  J.leftCols<3>().setIdentity();
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    J.rightCols<3>() = -skew(pairs.input[i]);
    g.noalias() += J.transpose() * (pairs.input[i] - pairs.reference[i]);
  }
  step.H = point_to_point_information(pairs.input);
  if (!solve_free_parameters(step.H, g, dof, &step.xi)) {
    step.problem = "point-to-point system is singular in the free parameters " + dof.to_string();
    return step;
  }
  step.delta = to_isometry(Pose6::from_vector(step.xi));  // eq. (3.8)
  step.ok = true;
  return step;
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

IcpStep point_to_point_step(const Correspondences& pairs, const DofMask& dof) {
  IcpStep step;
  const std::size_t n = pairs.size();
  if (n < 3 || pairs.reference.size() != n) {
    step.problem = "fewer than 3 point pairs";
    return step;
  }
  if (!dof.all()) {
    step = linearised_point_to_point_step(pairs, dof);
    if (step.ok) {
      step.score_before = mean_squared_distance(pairs, Eigen::Isometry3d::Identity());
      step.score_after = mean_squared_distance(pairs, step.delta);
    }
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

IcpStep point_to_plane_step(const Correspondences& pairs, const DofMask& dof) {
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
  // Gauss–Newton: H Δξ = −g.
  Vector6d dx;
  if (!solve_free_parameters(H, g, dof, &dx)) {
    step.problem = "point-to-plane system is singular in the free parameters " + dof.to_string() +
                   " (too few independent normal directions)";
    return step;
  }
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
