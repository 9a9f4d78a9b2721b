#include "sextant/synth/odometry.hpp"

#include <cmath>

#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"

namespace sextant::synth {
namespace {

Eigen::Isometry3d planar_isometry(const Increment2D& p) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(p.heading, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(p.forward, p.lateral, 0.0);
  return T;
}

/// Core Gaussian, widened by `scale` with probability `p` (heavy tails).
double heavy_tailed(double sigma, double p, double scale, Rng& rng) {
  const double wide = rng.uniform() < p ? scale : 1.0;
  return sigma * wide * rng.normal();
}

}  // namespace

Increment2D planar_pose(const Eigen::Isometry3d& T) {
  return {T.translation().x(), T.translation().y(), std::atan2(T.linear()(1, 0), T.linear()(0, 0))};
}

Increment2D planar_increment(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Increment2D pa = planar_pose(a), pb = planar_pose(b);
  const double c = std::cos(pa.heading), s = std::sin(pa.heading);
  const double dx = pb.forward - pa.forward, dy = pb.lateral - pa.lateral;
  return {c * dx + s * dy, -s * dx + c * dy, wrap_angle(pb.heading - pa.heading)};
}

Increment2D corrupt_increment(const Increment2D& truth, const OdometrySettings& s, Rng& rng) {
  Increment2D out = truth;
  if (s.model == "gaussian") {  // figs 5.32–5.34
    out.forward += rng.normal(0.0, s.gaussian_translation);
    out.lateral += rng.normal(0.0, s.gaussian_translation);
    out.heading += rng.normal(0.0, s.gaussian_heading_deg * kRadPerDeg);
    return out;
  }
  // "thesis": table 5.1, biased and heavy-tailed.
  out.forward += s.bias_forward + heavy_tailed(s.sigma_forward, s.outlier_probability, s.outlier_scale, rng);
  out.lateral += s.bias_lateral + heavy_tailed(s.sigma_lateral, s.outlier_probability, s.outlier_scale, rng);
  out.heading +=
      (s.bias_heading_deg + heavy_tailed(s.sigma_heading_deg, s.outlier_probability, s.outlier_scale, rng)) *
      kRadPerDeg;
  return out;
}

std::vector<Eigen::Isometry3d> simulate_odometry(const std::vector<Eigen::Isometry3d>& ground_truth,
                                                 const OdometrySettings& settings, Rng& rng) {
  std::vector<Eigen::Isometry3d> odometry;
  if (ground_truth.empty()) return odometry;
  odometry.push_back(planar_isometry(planar_pose(ground_truth.front())));
  for (std::size_t i = 1; i < ground_truth.size(); ++i) {
    const Increment2D step =
        corrupt_increment(planar_increment(ground_truth[i - 1], ground_truth[i]), settings, rng);
    odometry.push_back(odometry.back() * planar_isometry(step));
  }
  return odometry;
}

}  // namespace sextant::synth
