#pragma once
// Simulated 2D odometry (x, y, heading), as on the thesis' robot: the odometry pose has
// z = roll = pitch = 0 whatever the terrain (hannover1's odometry is 2D as well).
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/rng.hpp"
#include "sextant/synth/settings.hpp"

namespace sextant::synth {

/// A planar relative motion in the frame of the earlier pose [m, m, rad].
struct Increment2D {
  double forward = 0.0;
  double lateral = 0.0;
  double heading = 0.0;
};

/// Planar part of a 6D pose: (x, y) and the heading of its x axis.
Increment2D planar_pose(const Eigen::Isometry3d& T);
/// The planar motion from a to b expressed in a's planar frame.
Increment2D planar_increment(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);

/// A standard Student-t draw with ν > 0 degrees of freedom: t = z / √(χ²_ν / ν), z ~ N(0, 1) and
/// χ²_ν = 2 · Gamma(ν/2, 1) independent (the textbook construction, e.g. Johnson, Kotz &
/// Balakrishnan, Continuous Univariate Distributions vol. 2, ch. 28); the gamma variate by
/// Marsaglia & Tsang, "A simple method for generating gamma variables", ACM TOMS 26(3), 2000.
double student_t_draw(double dof, Rng& rng);

/// The true increment with the model's error added ("thesis": bias + core Gaussian, with a
/// chance of a wider "slip"; "gaussian": zero-mean N(0, σ) per component; "student_t": zero-mean
/// scale · t_ν per component).
Increment2D corrupt_increment(const Increment2D& truth, const OdometrySettings& settings, Rng& rng);

/// Dead-reckoned odometry poses: pose 0 is the planar part of ground_truth[0]; each next pose
/// composes the corrupted planar increment of the ground truth.
std::vector<Eigen::Isometry3d> simulate_odometry(const std::vector<Eigen::Isometry3d>& ground_truth,
                                                 const OdometrySettings& settings, Rng& rng);

}  // namespace sextant::synth
