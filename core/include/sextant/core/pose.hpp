#pragma once
// Pose conventions, written once. Internal frame: right-handed, metres, radians, x forward,
// y left, z up. A Pose6 (x, y, z, α, β, γ) means T = [R t; 0 1] with R = Rx(α)·Ry(β)·Rz(γ),
// the thesis' eq. (3.8) (whose printed Ry has a typo: its last row is [−sβ 0 cβ]) and 3DTK's
// EulerToMatrix4 order.
#include <Eigen/Core>
#include <string>

#include <Eigen/Geometry>

namespace sextant {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

struct Pose6 {
  double x = 0, y = 0, z = 0;             ///< translation [m]
  double alpha = 0, beta = 0, gamma = 0;  ///< Euler angles about x, y, z [rad], eq. (3.8)

  /// ξ = [tx ty tz α β γ]ᵀ, eq. (3.12).
  Vector6d vector() const;
  static Pose6 from_vector(const Vector6d& xi);
};

/// Wraps an angle to (−π, π].
double wrap_angle(double angle);

/// R = Rx(α)·Ry(β)·Rz(γ), eq. (3.8).
Eigen::Matrix3d rotation_from_euler(double alpha, double beta, double gamma);
/// Inverse of rotation_from_euler, β in [−π/2, π/2]; at gimbal lock (|cos β| ≈ 0) γ = 0.
Eigen::Vector3d euler_from_rotation(const Eigen::Matrix3d& R);

Eigen::Isometry3d to_isometry(const Pose6& pose);
Pose6 to_pose6(const Eigen::Isometry3d& T);

/// a ⊕ b = a·b.
Eigen::Isometry3d compose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);
Eigen::Isometry3d inverse(const Eigen::Isometry3d& T);
/// b ⊖ a = a⁻¹·b: the pose of b seen from a (the relative motion from a to b).
Eigen::Isometry3d relative(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);

/// Rotation angle of T's rotation part [rad], in [0, π].
double rotation_angle(const Eigen::Isometry3d& T);
/// Translation norm of T [m].
double translation_norm(const Eigen::Isometry3d& T);

/// True when every entry is finite.
bool is_finite(const Eigen::Isometry3d& T);

/// How far a rotation matrix read from a file may be from orthonormal (max |RᵀR − I|) and still be
/// taken as a rotation: pose files print 6–9 significant digits.
inline constexpr double kRigidTolerance = 1e-3;

/// Empty when R (with translation t) is a rigid transform — finite, max |RᵀR − I| ≤ `tolerance`,
/// det R > 0 — else what is wrong with it ("not orthonormal (max |RᵀR − I| = 1)", …). Every pose
/// reader checks its poses with it and names the file and line of a bad one.
std::string rigid_problem(const Eigen::Matrix3d& R, const Eigen::Vector3d& t,
                          double tolerance = kRigidTolerance);

/// The motion T continued for `factor` times as long at the same body-frame velocity: rotation
/// angle × factor about the same axis, translation × factor (a constant-velocity extrapolation,
/// exact for straight motion; factor 1 gives T, 0 the identity).
Eigen::Isometry3d scale_motion(const Eigen::Isometry3d& T, double factor);
bool is_finite(const Pose6& pose);

}  // namespace sextant
