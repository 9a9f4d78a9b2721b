// How the sequential chain deskews its scans (chain_deskew.hpp).
#include "chain_deskew.hpp"

#include <algorithm>
#include <utility>

#include "sequence_inputs.hpp"
#include "sextant/core/se3.hpp"

namespace sextant::odometry_detail {
namespace {

/// The sweep's velocity as a twist per second (zero for an unknown sweep).
Vector6d twist_per_second(const SweepMotion& sweep) {
  return sweep.known() ? Vector6d(se3_log(sweep.motion) / sweep.seconds) : Vector6d::Zero();
}

/// The farthest a point of `scan` moves when deskewed by `a` instead of `b`, to first order: the
/// velocities' difference (translation, and rotation times the range) over the sweep.
double largest_difference(const PointCloud& scan, const SweepMotion& a, const SweepMotion& b) {
  const Vector6d d = twist_per_second(a) - twist_per_second(b);
  float range = 0.0f;
  for (const Eigen::Vector3f& p : scan.points()) range = std::max(range, p.norm());
  return sweep_span(scan) * (d.head<3>().norm() + d.tail<3>().norm() * static_cast<double>(range));
}

}  // namespace

Eigen::Isometry3d mid_sweep_pose(const PointCloud& scan, const SweepMotion& sweep) {
  if (!scan.has_time() || !sweep.known()) return Eigen::Isometry3d::Identity();
  const auto [earliest, latest] = std::minmax_element(scan.time().begin(), scan.time().end());
  const double middle = 0.5 * (static_cast<double>(*earliest) + static_cast<double>(*latest));
  return interpolate_motion(sweep.motion, middle / sweep.seconds);
}

ChainDeskew::ChainDeskew(const Dataset& dataset, std::size_t first, bool enabled, OdometryResult& result)
    : dataset_(dataset), first_(first), enabled_(enabled), result_(result) {}

PointCloud ChainDeskew::take(std::size_t k, PointCloud scan,
                             const std::optional<Eigen::Isometry3d>& odometry_motion) {
  result_.timed_scans += scan.has_time() ? 1 : 0;
  if (!enabled_) return scan;
  if (odometry_motion) {
    const std::size_t from = k == 0 ? 0 : k - 1;
    result_.sweeps[k] = sweep_between(dataset_, first_ + from, first_ + from + 1, scan, *odometry_motion);
  } else if (scan.has_time()) {
    result_.sweeps[k] = velocity_;
  }
  PointCloud taken = deskew_scan(scan, result_.sweeps[k]);
  raw_.push_back(scan.has_time() ? std::move(scan) : PointCloud());
  return taken;
}

SweepMotion ChainDeskew::step_velocity(std::size_t k, const Eigen::Isometry3d& relative) const {
  if (!enabled_ || k == 0 || raw_.size() < 2 || !raw_.back().has_time()) return {};
  const PointCloud& before = raw_[raw_.size() - 2];
  const PointCloud& now = raw_.back();
  const Eigen::Isometry3d middles = mid_sweep_pose(before, result_.sweeps[k - 1]).inverse() * relative *
                                    mid_sweep_pose(now, result_.sweeps[k]);
  // Made in the step's time: its stamps', else one sweep (scans back to back).
  return sweep_between(dataset_, first_ + k - 1, first_ + k, now, middles);
}

bool ChainDeskew::deskew_the_rest(std::deque<PointCloud>& window, std::size_t newest,
                                  const SweepMotion& velocity) {
  bool any = false;
  // window[j] is scan newest + 1 − window.size() + j; raw_[j] its points as read.
  for (std::size_t j = 0; j < window.size() && j < raw_.size(); ++j) {
    const std::size_t index = newest + 1 + j - window.size();
    if (!raw_[j].has_time() || result_.sweeps[index].known()) continue;
    result_.sweeps[index] = velocity;
    window[j] = deskew_scan(raw_[j], velocity);
    any = true;
  }
  return any;
}

std::optional<PointCloud> ChainDeskew::deskewed_again(std::size_t k, const Eigen::Isometry3d& relative,
                                                      std::deque<PointCloud>& window, bool& map_changed) {
  map_changed = false;
  if (raw_.size() != window.size() + 1) return std::nullopt;  // deskew off
  const SweepMotion measured = step_velocity(k, relative);
  if (!measured.known() ||
      largest_difference(raw_.back(), measured, result_.sweeps[k]) <= kRegisterAgainMetres)
    return std::nullopt;
  map_changed = deskew_the_rest(window, k - 1, measured);
  first_sweep_ = result_.sweeps[k];
  result_.sweeps[k] = measured;
  return deskew_scan(raw_.back(), measured);
}

void ChainDeskew::keep_first(std::size_t k) {
  result_.sweeps[k] = first_sweep_;
}

void ChainDeskew::learn(std::size_t k, const Eigen::Isometry3d& relative, std::deque<PointCloud>& window) {
  if (raw_.size() != window.size()) return;  // deskew off
  const SweepMotion measured = step_velocity(k, relative);
  if (!measured.known()) return;
  velocity_ = measured;
  deskew_the_rest(window, k, velocity_);
}

void ChainDeskew::keep_last(std::size_t n) {
  while (raw_.size() > n) raw_.pop_front();
}

}  // namespace sextant::odometry_detail
