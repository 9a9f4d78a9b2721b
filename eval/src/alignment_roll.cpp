#include "sextant/eval/alignment_roll.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

namespace sextant {

Similarity3 resolve_roll_about_trajectory(const Similarity3& alignment, const PoseList& estimate,
                                          const PoseList& reference, bool* resolved) {
  if (resolved) *resolved = false;
  const std::size_t n = reference.size();
  if (!alignment.ok || n < 2 || estimate.size() != n) return alignment;
  Eigen::Vector3d mean_ref = Eigen::Vector3d::Zero(), mean_est = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    mean_ref += reference[i].translation();
    mean_est += estimate[i].translation();
  }
  mean_ref /= double(n);
  mean_est /= double(n);
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  double residual = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d d = reference[i].translation() - mean_ref;
    spread += d * d.transpose();
    residual += (reference[i].translation() - alignment.apply(estimate[i].translation())).squaredNorm();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal(spread / double(n));
  const Eigen::Vector3d& variances = principal.eigenvalues();                   // ascending
  const double across = std::sqrt(std::max(0.0, variances(0) + variances(1)));  // RMS distance from a [m]
  const double unexplained = std::sqrt(residual / double(n));                   // RMS residual [m]
  // The roll the positions leave free [rad]; on one line (across = 0) any roll fits.
  const double position_roll = across > 0.0 ? unexplained / across : std::numeric_limits<double>::infinity();
  if (!(position_roll > kRollTolerance)) return alignment;
  const Eigen::Vector3d axis = principal.eigenvectors().col(2);
  double sin_sum = 0.0, cos_sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Quaterniond q(
        Eigen::Matrix3d(reference[i].linear() * (alignment.rotation * estimate[i].linear()).transpose()));
    const double twist = 2.0 * std::atan2(q.vec().dot(axis), q.w());
    sin_sum += std::sin(twist);
    cos_sum += std::cos(twist);
  }
  // The twists' circular standard deviation √(−2 ln R̄) [rad]: how closely the orientations fix it.
  const double length = std::hypot(sin_sum, cos_sum) / double(n);
  if (!(length > 0.0)) return alignment;
  const double orientation_roll = std::sqrt(std::max(0.0, -2.0 * std::log(std::min(1.0, length))));
  if (!(orientation_roll < position_roll)) return alignment;
  Similarity3 out = alignment;
  out.rotation =
      Eigen::AngleAxisd(std::atan2(sin_sum, cos_sum), axis).toRotationMatrix() * alignment.rotation;
  out.translation = mean_ref - out.scale * out.rotation * mean_est;
  if (resolved) *resolved = true;
  return out;
}

}  // namespace sextant
