#include "kit/fbmlndt_motion.hpp"

#include <chrono>
#include <cmath>

#include <Eigen/Cholesky>
#include "sextant/matchers/yaml.hpp"

namespace sextant {
namespace {

using Clock = std::chrono::steady_clock;

/// The odometry increment u as a rigid transform (previous ← current): the registration's initial
/// guess. u's angles are Euler differences; at the previous orientation o the relative rotation is
/// R(o)ᵀ·R(o + δo).
Eigen::Isometry3d increment_transform(const Vector6d& from, const Vector6d& u) {
  const Eigen::Matrix3d Ro = rotation_from_euler(from[3], from[4], from[5]);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Ro.transpose() * rotation_from_euler(from[3] + u[3], from[4] + u[4], from[5] + u[5]);
  T.translation() = u.head<3>();
  return T;
}

}  // namespace

FbmlndtMotion::FbmlndtMotion(const YAML::Node& matcher, const HybridParams& params, const std::string& file)
    : matcher_(read_mlndt_settings(matcher, file)), params_(params) {}

HybridMotion FbmlndtMotion::motion(const PointCloud& previous, const PointCloud& current,
                                   const PlaneExtraction& extraction, const Vector6d& from,
                                   const MotionIncrement& odometry) {
  const auto t0 = Clock::now();
  HybridMotion out;
  out.motion = odometry;
  const auto done = [&](std::string reason) {
    out.reason = std::move(reason);
    out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return out;
  };
  // The shared extraction's cell planes: FbML-NDT's sample and its degeneracy check.
  const ConstraintCheck check = check_plane_constraints(extraction.cell_planes, current, constraints_);
  if (!check.constrains_all) return done("sample degenerate: " + check.reason);
  const PointCloud sample = current.subset(extraction.cell_inlier_indices());
  matcher_.set_reference(previous);
  const RegistrationResult r = matcher_.align(sample, increment_transform(from, odometry.u));
  if (!r.converged) return done("not converged (" + to_string(r.why) + ")");
  const Eigen::LLT<Matrix6d> llt(r.H);
  if (!r.H.allFinite() || llt.info() != Eigen::Success) return done("H not positive definite");
  const Matrix6d covariance = params_.noise_scale * llt.solve(Matrix6d::Identity());  // eq. (3.50)
  const MotionIncrement m = increment_from_relative_pose(from, r.T, covariance);
  const Vector6d d = m.u - odometry.u;
  double angle = 0.0;
  for (int i = 3; i < 6; ++i) angle = std::max(angle, std::abs(wrap_angle(d[i])));
  if (d.head<3>().norm() > params_.alarm_translation || angle > params_.alarm_rotation)
    return done("alarm: matcher and odometry disagree");
  out.motion = m;
  out.matched = true;
  return done("");
}

}  // namespace sextant
