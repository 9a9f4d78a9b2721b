#include "sextant/matchers/sensor_kind.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "sextant/core/error.hpp"
#include "sextant/core/units.hpp"

namespace sextant {

bool from_string(const std::string& text, SensorKind* out) {
  return from_name(kSensorKindNames, text, out);
}

std::string to_string(SensorKind kind) {
  return name_of(kSensorKindNames, kind);
}

SensorDetection detect_sensor(const PointCloud& scan) {
  std::array<std::size_t, kAzimuthSectors> counts{};
  std::size_t n = 0;
  for (const Eigen::Vector3f& p : scan.points()) {
    if (!p.allFinite() || (p.x() == 0.0f && p.y() == 0.0f)) continue;
    const double azimuth = std::atan2(static_cast<double>(p.y()), static_cast<double>(p.x()));  // (−π, π]
    auto sector = static_cast<int>(std::floor((azimuth + kPi) / (2.0 * kPi) * kAzimuthSectors));
    sector = std::min(std::max(sector, 0), kAzimuthSectors - 1);
    ++counts[static_cast<std::size_t>(sector)];
    ++n;
  }
  SensorDetection d;
  if (n == 0) {
    d.azimuth_coverage = 0.0;
    return d;
  }
  // A sector counts when it holds at least 1/20 of an even share: a few stray returns (a reflection,
  // the platform's own body) do not make a sector seen.
  const double enough = std::max(1.0, static_cast<double>(n) / (20.0 * kAzimuthSectors));
  int covered = 0;
  for (const std::size_t c : counts) covered += static_cast<double>(c) >= enough ? 1 : 0;
  d.azimuth_coverage = static_cast<double>(covered) / kAzimuthSectors;
  d.kind = d.azimuth_coverage >= kSpinningCoverage ? SensorKind::spinning : SensorKind::solid_state;
  return d;
}

SensorDetection resolve_sensor(SensorKind declared, const PointCloud& scan) {
  SensorDetection d = detect_sensor(scan);
  if (declared != SensorKind::automatic) d.kind = declared;
  return d;
}

}  // namespace sextant
