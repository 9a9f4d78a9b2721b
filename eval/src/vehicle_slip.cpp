// A car's sideways slip per step (vehicle_slip.hpp).
#include "sextant/eval/vehicle_slip.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sextant {
namespace {

struct PlanarStep {
  double x = 0.0, y = 0.0;  ///< the chord in the start pose's horizontal plane [m]
  double turn = 0.0;        ///< the heading change [rad]
};

PlanarStep planar_step(const Eigen::Isometry3d& from, const Eigen::Isometry3d& to) {
  const Eigen::Isometry3d step = from.inverse() * to;
  const Eigen::Matrix3d& R = step.linear();
  return {step.translation().x(), step.translation().y(), std::atan2(R(1, 0), R(0, 0))};
}

/// `angle` as the same axis in (−π/2, π/2] [rad].
double half_turn_offset(double angle) {
  angle = std::remainder(angle, M_PI);  // [−π/2, π/2]
  return angle <= -0.5 * M_PI ? angle + M_PI : angle;
}

}  // namespace

std::vector<std::size_t> VehicleSlip::slipping(double limit) const {
  std::vector<std::size_t> steps;
  for (std::size_t k = 0; k < slip.size(); ++k)
    if (std::abs(slip[k]) > limit) steps.push_back(k);
  return steps;
}

VehicleSlip vehicle_slip(const std::vector<Eigen::Isometry3d>& poses, double min_chord) {
  std::vector<PlanarStep> steps;
  for (std::size_t k = 0; k + 1 < poses.size(); ++k) steps.push_back(planar_step(poses[k], poses[k + 1]));
  // The start heading of an arc is its chord's direction less half the turn; forward and reverse
  // steps give opposite headings of one axis. Their chord-weighted mean as doubled angles, then the
  // median of the axes' offsets from it: a few slipping steps do not move it.
  std::vector<double> axes;
  double c = 0.0, s = 0.0;
  for (const PlanarStep& p : steps) {
    const double chord = std::hypot(p.x, p.y);
    if (!(chord >= min_chord)) continue;
    axes.push_back(std::atan2(p.y, p.x) - 0.5 * p.turn);
    c += chord * std::cos(2.0 * axes.back());
    s += chord * std::sin(2.0 * axes.back());
  }
  VehicleSlip result;
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  result.mounting = kNaN;
  if (!axes.empty() && (c != 0.0 || s != 0.0)) {
    const double mean = 0.5 * std::atan2(s, c);
    for (double& axis : axes) axis = half_turn_offset(axis - mean);
    const auto mid = axes.begin() + static_cast<std::ptrdiff_t>(axes.size() / 2);
    std::nth_element(axes.begin(), mid, axes.end());
    result.mounting = half_turn_offset(mean + *mid);
  }
  for (const PlanarStep& p : steps) {
    // The chord across the axis turned by half the step's turn.
    const double axis = result.mounting + 0.5 * p.turn;
    result.slip.push_back(std::isnan(axis) ? kNaN : -p.x * std::sin(axis) + p.y * std::cos(axis));
  }
  return result;
}

}  // namespace sextant
