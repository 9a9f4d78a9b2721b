// What two scans can both see (common_view.hpp).
#include "sextant/odometry/common_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "sextant/core/units.hpp"

namespace sextant {
namespace {

/// The elevation band of a view is widened by 1° on each side: a beam's divergence, and the tilt a
/// guess may get wrong, so that a planar scanner (every point at elevation 0) still sees its own plane
/// from a slightly tilted guess [rad].
constexpr double kMargin = 1.0 * kRadPerDeg;
constexpr double kHalfTurn = 0.5 * kPi;  // straight up or down [rad]

/// z ≥ slope · √horizontal2 without the root (squares compared on the side of zero where both lie),
/// true for slope = −∞ (`open`). The sign of the slope selects by bit operations, not a branch, so
/// that a loop over points vectorizes.
bool at_least(float z, float slope, float horizontal2, bool open) {
  const float bound2 = slope * slope * horizontal2;
  const bool falls = slope <= 0.0f, up = z >= 0.0f;
  return open | (falls & (up | (z * z <= bound2))) | (!falls & up & (z * z >= bound2));
}

/// The elements of `all` whose `keep` is 1, in order, into `kept`: each is written where the next kept one
/// goes and the position moves on by its flag, with no branch.
template <typename Elements, typename T>
void compact(const Elements& all, const std::vector<std::uint8_t>& keep, std::vector<T>& kept) {
  kept.resize(keep.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < keep.size(); ++i) {
    kept[k] = all[i];
    k += keep[i];
  }
  kept.resize(k);
}

/// The points of `cloud` that `view` sees once `to_sensor` (sensor ← cloud's frame) moves them:
/// SensorView::sees in single precision, as the points are stored (the view's edges are a degree
/// wide), without a root or a branch per point: a local map holds 10⁵ points, and every step cuts one.
/// The test runs over all points first and the kept ones are then copied in order, so that neither
/// loop carries a dependency from one point to the next but the count.
PointCloud seen(const PointCloud& cloud, const SensorView& view, const Eigen::Isometry3d& to_sensor) {
  const Eigen::Matrix3f R = to_sensor.linear().cast<float>();
  const Eigen::Vector3f t = to_sensor.translation().cast<float>();
  const float range2 = static_cast<float>(view.max_range * view.max_range);
  const float low = static_cast<float>(view.min_slope), high = static_cast<float>(view.max_slope);
  // In the sector: the horizontal direction's component along the sector's centre at least cos(half
  // width) × its length, the elevation test's form (at_least).
  const bool whole_circle = view.azimuth_half_width >= kPi;
  const float cx = static_cast<float>(std::cos(view.azimuth_centre)),
              cy = static_cast<float>(std::sin(view.azimuth_centre)),
              cos_half = static_cast<float>(std::cos(std::min(view.azimuth_half_width, kPi)));
  const bool open_below = view.min_slope == -std::numeric_limits<double>::infinity(),
             open_above = view.max_slope == std::numeric_limits<double>::infinity();
  const PointsView points = cloud.points();
  const std::size_t n = points.size();
  const float* xyz = cloud.data();  // x, y, z of point i at 3i, 3i + 1, 3i + 2
  const float r00 = R(0, 0), r01 = R(0, 1), r02 = R(0, 2), r10 = R(1, 0), r11 = R(1, 1), r12 = R(1, 2),
              r20 = R(2, 0), r21 = R(2, 1), r22 = R(2, 2), tx = t.x(), ty = t.y(), tz = t.z();
  std::vector<std::uint8_t> sees(n);
  for (std::size_t i = 0; i < n; ++i) {
    const float px = xyz[3 * i], py = xyz[3 * i + 1], pz = xyz[3 * i + 2];
    const float x = r00 * px + r01 * py + r02 * pz + tx, y = r10 * px + r11 * py + r12 * pz + ty,
                z = r20 * px + r21 * py + r22 * pz + tz;
    const float horizontal2 = x * x + y * y;
    const bool in_range = horizontal2 + z * z <= range2;  // NaN fails it
    const bool above = at_least(z, low, horizontal2, open_below);
    const bool below = at_least(-z, -high, horizontal2, open_above);
    const bool in_sector = at_least(x * cx + y * cy, cos_half, horizontal2, whole_circle);
    sees[i] = static_cast<std::uint8_t>(in_range & above & below & in_sector);
  }
  PointCloud out;
  compact(points, sees, out.mutable_points());
  if (cloud.has_intensity()) compact(cloud.intensity(), sees, out.intensity());
  return out;
}

}  // namespace

bool SensorView::sees(const Eigen::Vector3d& p) const {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const double horizontal = std::sqrt(p.x() * p.x() + p.y() * p.y());
  const bool in_sector =
      azimuth_half_width >= kPi || p.x() * std::cos(azimuth_centre) + p.y() * std::sin(azimuth_centre) >=
                                       std::cos(azimuth_half_width) * horizontal;
  return p.squaredNorm() <= max_range * max_range &&
         (min_slope == -kInfinity || p.z() >= min_slope * horizontal) &&
         (max_slope == kInfinity || p.z() <= max_slope * horizontal) && in_sector;
}

namespace {

/// Sets `view`'s sector from the azimuths of a scan's points (sensor_view): the circle less its largest
/// gap between neighbouring azimuths, when that gap is more than half the circle, widened by kMargin on
/// each side.
void set_sector(SensorView& view, std::vector<double> azimuths) {
  if (azimuths.size() < 2) return;
  std::sort(azimuths.begin(), azimuths.end());
  double gap = azimuths.front() + 2.0 * kPi - azimuths.back();  // across ±π
  double gap_end = azimuths.front();
  for (std::size_t i = 1; i < azimuths.size(); ++i)
    if (azimuths[i] - azimuths[i - 1] > gap) {
      gap = azimuths[i] - azimuths[i - 1];
      gap_end = azimuths[i];
    }
  if (!(gap > kPi)) return;  // a spinning lidar's view: the whole circle
  const double width = 2.0 * kPi - gap;
  view.azimuth_centre = gap_end + 0.5 * width;
  view.azimuth_half_width = 0.5 * width + kMargin;
}

}  // namespace

SensorView sensor_view(const PointCloud& scan, SensorKind sensor) {
  SensorView view;
  view.min_slope = std::numeric_limits<double>::infinity();
  view.max_slope = -std::numeric_limits<double>::infinity();
  std::vector<double> azimuths;
  azimuths.reserve(scan.size());
  for (const Eigen::Vector3f& q : scan.points()) {
    const Eigen::Vector3d p = q.cast<double>();
    if (!p.allFinite()) continue;
    view.max_range = std::max(view.max_range, p.norm());
    const double horizontal = std::sqrt(p.x() * p.x() + p.y() * p.y());
    if (!(horizontal > 0.0)) continue;
    view.min_slope = std::min(view.min_slope, p.z() / horizontal);
    view.max_slope = std::max(view.max_slope, p.z() / horizontal);
    azimuths.push_back(std::atan2(p.y(), p.x()));
  }
  if (!(view.min_slope <= view.max_slope)) return view;  // no point off the vertical: sees nothing
  if (sensor == SensorKind::solid_state) set_sector(view, std::move(azimuths));
  // The band widened by kMargin on each side, open where it reaches straight down or up.
  const double low = std::atan(view.min_slope) - kMargin, high = std::atan(view.max_slope) + kMargin;
  view.min_slope = low <= -kHalfTurn ? -std::numeric_limits<double>::infinity() : std::tan(low);
  view.max_slope = high >= kHalfTurn ? std::numeric_limits<double>::infinity() : std::tan(high);
  return view;
}

std::pair<PointCloud, PointCloud> common_view(const PointCloud& reference, const SensorView& reference_view,
                                              const PointCloud& input, const SensorView& input_view,
                                              const Eigen::Isometry3d& guess) {
  return {seen(reference, input_view, guess.inverse()), seen(input, reference_view, guess)};
}

}  // namespace sextant
