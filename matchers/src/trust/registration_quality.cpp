#include "sextant/matchers/registration_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Eigenvalues>

#include <fmt/format.h>

#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"

namespace sextant {

std::string to_string(Trust trust) {
  switch (trust) {
    case Trust::kOk: return "ok";
    case Trust::kNotConverged: return "not_converged";
    case Trust::kDegenerate: return "degenerate";
    case Trust::kLowOverlap: return "low_overlap";
    case Trust::kSuspect: return "suspect";
  }
  return "unknown";
}

bool QualitySettings::valid(std::string* why) const {
  const char* problem = nullptr;
  if (!(min_overlap >= 0.0 && min_overlap <= 1.0))
    problem = "min_overlap must lie in [0, 1]";
  else if (!(min_constraint_ratio >= 0.0 && min_constraint_ratio < 1.0))
    problem = "min_constraint_ratio must lie in [0, 1)";
  else if (!(max_fit_ratio > 0.0))
    problem = "max_fit_ratio must be positive (.inf: no fit check)";
  else if (!(ambiguity_metres > 0.0) || !(ambiguity_degrees > 0.0))
    problem = "ambiguity_metres and ambiguity_degrees must be positive (.inf: no ambiguity check)";
  else if (!(ambiguity_fit_band >= 1.0))
    problem = "ambiguity_fit_band must be at least 1";
  if (problem && why) *why = problem;
  return problem == nullptr;
}

double rms_range(const PointCloud& cloud) {
  double sum = 0.0;
  std::size_t n = 0;
  for (const Eigen::Vector3f& p : cloud.points()) {
    const double d = p.cast<double>().squaredNorm();
    if (!std::isfinite(d)) continue;
    sum += d;
    ++n;
  }
  return n == 0 || sum == 0.0 ? 1.0 : std::sqrt(sum / static_cast<double>(n));
}

double constraint_ratio(const Matrix6d& H, double range, const DofMask& free) {
  if (!H.allFinite() || !(range > 0.0)) return 0.0;
  if (H.isZero(0.0)) return std::numeric_limits<double>::quiet_NaN();  // the matcher gives no H
  std::vector<int> active;  // the parameters the registration could move; a zero row among them: 0
  for (int i = 0; i < 6; ++i)
    if (free.active[static_cast<std::size_t>(i)]) active.push_back(i);
  if (active.empty()) return std::numeric_limits<double>::quiet_NaN();
  const int n = static_cast<int>(active.size());
  Eigen::MatrixXd scaled(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const int a = active[static_cast<std::size_t>(i)], b = active[static_cast<std::size_t>(j)];
      const double sa = a < 3 ? 1.0 : 1.0 / range, sb = b < 3 ? 1.0 : 1.0 / range;
      scaled(i, j) = 0.5 * (H(a, b) + H(b, a)) * sa * sb;  // S·H·S, rotations in metres at `range`
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(scaled, Eigen::EigenvaluesOnly);
  Eigen::VectorXd l = eig.eigenvalues();
  if (l.maxCoeff() <= 0.0) l = -l;  // the Hessian of a maximised score (PCL's NDT) is negative definite
  const double strongest = l.maxCoeff();
  if (!(strongest > 0.0)) return 0.0;
  return std::max(0.0, l.minCoeff()) / strongest;  // an indefinite H: 0
}

bool far_apart(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, const QualitySettings& settings) {
  const Eigen::Isometry3d d = relative(a, b);
  return translation_norm(d) > settings.ambiguity_metres ||
         rotation_angle(d) * kDegPerRad > settings.ambiguity_degrees;
}

bool rivals(const Eigen::Isometry3d& pose, double fit, const Eigen::Isometry3d& other, double other_fit,
            const QualitySettings& settings) {
  return far_apart(pose, other, settings) && other_fit <= settings.ambiguity_fit_band * fit;
}

namespace {

/// The checks on `result` alone (its alternatives left out).
RegistrationQuality assess_alone(const RegistrationResult& result, const PointCloud& input,
                                 const QualitySettings& settings) {
  RegistrationQuality q;
  q.assessed = true;
  q.overlap = result.input_points == 0
                  ? 0.0
                  : static_cast<double>(result.matched_points) / static_cast<double>(result.input_points);
  q.constraint_ratio =
      constraint_ratio(result.constraint_hessian.isZero(0.0) ? result.H : result.constraint_hessian,
                       rms_range(input), result.free);
  if (result.predicted_matched_score > 0.0 && std::isfinite(result.mean_matched_score))
    q.fit_ratio = result.mean_matched_score / result.predicted_matched_score;
  if (!result.converged) {
    q.trust = Trust::kNotConverged;
    q.reason = "the optimiser did not converge (" + to_string(result.why) + ")";
  } else if (q.overlap < settings.min_overlap) {
    q.trust = Trust::kLowOverlap;
    q.reason = fmt::format("{:.1f} % of the input matched, below {:.0f} %", 100.0 * q.overlap,
                           100.0 * settings.min_overlap);
  } else if (!std::isnan(q.constraint_ratio) && q.constraint_ratio < settings.min_constraint_ratio) {
    q.trust = Trust::kDegenerate;
    q.reason = fmt::format("the weakest direction is constrained {:.2g} × the strongest, below {:.2g}",
                           q.constraint_ratio, settings.min_constraint_ratio);
  } else if (q.fit_ratio > settings.max_fit_ratio) {
    q.trust = Trust::kSuspect;
    q.reason = fmt::format("matched points score {:.2f} × what a right pose predicts, above {:.2f}",
                           q.fit_ratio, settings.max_fit_ratio);
  } else {
    q.trust = Trust::kOk;
  }
  return q;
}

}  // namespace

RegistrationQuality assess_registration(const RegistrationResult& result, const PointCloud& input,
                                        const QualitySettings& settings) {
  RegistrationQuality q = assess_alone(result, input, settings);
  if (!q.trusted()) return q;
  // Solutions are told apart where the pyramid ended them (before_precision): at one stage's precision.
  const Eigen::Isometry3d mine = result.before_precision.value_or(result.T);
  for (const RegistrationResult& other : result.alternatives) {
    const RegistrationQuality alone = assess_alone(other, input, settings);
    const Eigen::Isometry3d theirs = other.before_precision.value_or(other.T);
    if (!alone.trusted() || !rivals(mine, q.fit_ratio, theirs, alone.fit_ratio, settings)) continue;
    const Eigen::Isometry3d d = relative(mine, theirs);
    q.trust = Trust::kSuspect;
    q.ambiguous = true;
    q.reason = fmt::format(
        "ambiguous: another solution {:.2f} m and {:.1f}° away passes the same checks (fit {:.2f}, overlap "
        "{:.2f})",
        translation_norm(d), rotation_angle(d) * kDegPerRad, alone.fit_ratio, alone.overlap);
    break;
  }
  return q;
}

}  // namespace sextant
