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

namespace student_t_noise {

/// Gamma(shape, 1) by Marsaglia & Tsang (2000), §2 (shape ≥ 1) and its §6 boost for shape < 1:
/// Gamma(a) = Gamma(a + 1) · U^(1/a).
double gamma_draw(double shape, Rng& rng) {
  if (shape < 1.0) {
    const double boosted = gamma_draw(shape + 1.0, rng);  // drawn before U, on every compiler
    return boosted * std::pow(1.0 - rng.uniform(), 1.0 / shape);
  }
  const double d = shape - 1.0 / 3.0, c = 1.0 / std::sqrt(9.0 * d);
  for (;;) {
    const double x = rng.normal();
    const double t = 1.0 + c * x;
    if (t <= 0.0) continue;
    const double v = t * t * t;
    const double u = 1.0 - rng.uniform();  // (0, 1]: the logarithm below stays finite
    if (u < 1.0 - 0.0331 * x * x * x * x) return d * v;
    if (std::log(u) < 0.5 * x * x + d * (1.0 - v + std::log(v))) return d * v;
  }
}

}  // namespace student_t_noise

double student_t_draw(double dof, Rng& rng) {
  const double z = rng.normal();
  const double chi2 = 2.0 * student_t_noise::gamma_draw(0.5 * dof, rng);  // χ²_ν = 2 · Gamma(ν/2)
  return z / std::sqrt(chi2 / dof);
}

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
  if (s.model == "student_t") {  // zero mean, scale · t_ν per component (issue 27's heavy tails)
    out.forward += s.student_t_translation * student_t_draw(s.student_t_dof, rng);
    out.lateral += s.student_t_translation * student_t_draw(s.student_t_dof, rng);
    out.heading += s.student_t_heading_deg * kRadPerDeg * student_t_draw(s.student_t_dof, rng);
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
