#pragma once
// The model a SLAM filter runs on (§4.2, §5.2.1.3 A): a vehicle model f, an observation model h
// of one landmark and an augmentation model g, each with analytic Jacobians. The filter state is
// x = [x_v; m_1; …; m_N] (eq. 4.55): pose_dim() pose entries then landmark_dim() per landmark.
// The same filters run the 6D plane-landmark problem, the 2D range–bearing point-landmark
// problem and a linear-Gaussian test problem through this interface.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace sextant {

class SlamModel {
 public:
  virtual ~SlamModel() = default;
  virtual std::string name() const = 0;
  virtual int pose_dim() const = 0;
  virtual int control_dim() const = 0;
  virtual int landmark_dim() const = 0;
  virtual int observation_dim() const = 0;

  /// Vehicle model x_v' = f(x_v, u) (noise-free, control noise enters through u).
  virtual Eigen::VectorXd process(const Eigen::VectorXd& pose, const Eigen::VectorXd& u) const = 0;
  /// ∂f/∂x_v, eq. (4.62).
  virtual Eigen::MatrixXd process_jacobian_pose(const Eigen::VectorXd& pose,
                                                const Eigen::VectorXd& u) const = 0;
  /// ∂f/∂u.
  virtual Eigen::MatrixXd process_jacobian_control(const Eigen::VectorXd& pose,
                                                   const Eigen::VectorXd& u) const = 0;

  /// Observation of one landmark from the pose, z = h(x_v, m).
  virtual Eigen::VectorXd observe(const Eigen::VectorXd& pose, const Eigen::VectorXd& landmark) const = 0;
  /// ∂h/∂x_v and ∂h/∂m, eq. (4.65).
  virtual Eigen::MatrixXd observe_jacobian_pose(const Eigen::VectorXd& pose,
                                                const Eigen::VectorXd& landmark) const = 0;
  virtual Eigen::MatrixXd observe_jacobian_landmark(const Eigen::VectorXd& pose,
                                                    const Eigen::VectorXd& landmark) const = 0;

  /// New landmark from the pose and its observation, m = g(x_v, z).
  virtual Eigen::VectorXd augment(const Eigen::VectorXd& pose, const Eigen::VectorXd& z) const = 0;
  /// G_v = ∂g/∂x_v and G_z = ∂g/∂z, eq. (4.67).
  virtual Eigen::MatrixXd augment_jacobian_pose(const Eigen::VectorXd& pose,
                                                const Eigen::VectorXd& z) const = 0;
  virtual Eigen::MatrixXd augment_jacobian_observation(const Eigen::VectorXd& pose,
                                                       const Eigen::VectorXd& z) const = 0;

  /// Indices of the pose / observation entries that are angles (wrapped to (−π, π]).
  virtual std::vector<int> pose_angles() const { return {}; }
  virtual std::vector<int> observation_angles() const { return {}; }
  /// Brings a measured z into the sign convention of the predicted one (a plane (n, d) and
  /// (−n, −d) are the same plane). Default: unchanged.
  virtual Eigen::VectorXd align_observation(const Eigen::VectorXd& z,
                                            const Eigen::VectorXd& /*predicted*/) const {
    return z;
  }
  /// Puts a landmark into its canonical form in place (planes: unit normal). Default: unchanged.
  virtual void normalize_landmark(Eigen::Ref<Eigen::VectorXd> /*landmark*/) const {}
};

/// Number of landmarks in a state vector of the given size.
int landmark_count(const SlamModel& model, Eigen::Index state_size);
/// Offset of landmark `index` (0-based) in the state vector.
Eigen::Index landmark_offset(const SlamModel& model, int index);

/// Wraps v[offset + i] for every i in `angles`.
void wrap_entries(Eigen::Ref<Eigen::VectorXd> v, const std::vector<int>& angles, Eigen::Index offset = 0);
/// a − b over a full state, with the pose angles wrapped.
Eigen::VectorXd state_difference(const SlamModel& model, const Eigen::VectorXd& a, const Eigen::VectorXd& b);
/// Wraps the pose angles and normalises every landmark of a full state in place.
void normalize_state(const SlamModel& model, Eigen::Ref<Eigen::VectorXd> x);

}  // namespace sextant
