#include "sextant/odometry/platform.hpp"

#include <algorithm>
#include <vector>

#include "sextant/core/error.hpp"

namespace sextant {

bool from_string(const std::string& text, Platform* out) {
  return from_name(kPlatformNames, text, out);
}

std::string to_string(Platform platform) {
  return name_of(kPlatformNames, platform);
}

QualitySettings platform_tolerance(const QualitySettings& base, Platform platform,
                                   std::optional<double> typical_step) {
  QualitySettings q = base;
  const double low_m = std::min(kHandheldToleranceMetres, base.ambiguity_metres);
  const double low_deg = std::min(kHandheldToleranceDegrees, base.ambiguity_degrees);
  if (platform == Platform::car || (platform == Platform::automatic && !typical_step)) return q;
  const double metres =
      platform == Platform::handheld ? low_m : std::clamp(0.5 * *typical_step, low_m, base.ambiguity_metres);
  const double span = base.ambiguity_metres - low_m;
  const double along = span > 0.0 ? (metres - low_m) / span : 1.0;
  q.ambiguity_metres = metres;
  q.ambiguity_degrees = low_deg + along * (base.ambiguity_degrees - low_deg);
  return q;
}

void MotionScale::record(const Eigen::Isometry3d& trusted_step) {
  lengths_.push_back(trusted_step.translation().norm());
  while (lengths_.size() > window_) lengths_.pop_front();
}

std::optional<double> MotionScale::typical_step() const {
  if (lengths_.size() < std::max<std::size_t>(min_history_, 1)) return std::nullopt;
  std::vector<double> v(lengths_.begin(), lengths_.end());
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace sextant
