#pragma once
// Which kind of lidar took a scan (issue 62). Some trust checks rest on a property of one kind: a
// spinning lidar's ground rings are circles about the sensor, so two of its scans coincide at no
// translation whatever the platform did, and the points above its horizon hold no ring
// (horizon_check.hpp, check_unconfirmed_no_motion in sequence_trust.hpp). A solid-state lidar (a
// rosette or other non-repetitive pattern over a field of view of some tens of degrees) draws no
// rings: two of its scans from one place do not repeat each other's points, and nothing holds a
// registration at no motion. Those checks apply only where the sensor spins, declared or measured:
// a spinning lidar sees the whole azimuth circle, a solid-state one a sector of it.
#include <string>

#include "sextant/core/enum_names.hpp"
#include "sextant/core/point_cloud.hpp"

namespace sextant {

enum class SensorKind {
  automatic,    ///< measured from the data (detect_sensor)
  spinning,     ///< a rotating multi-beam lidar (rings, 360° of azimuth)
  solid_state,  ///< a fixed field of view, no rings (e.g. a Livox's rosette)
};

/// The names: "auto", "spinning", "solid_state" (parse_enum(kSensorKindNames, text, what) for a user's).
inline constexpr EnumNames<SensorKind, 3> kSensorKindNames{"sensor",
                                                           {{{SensorKind::automatic, "auto"},
                                                             {SensorKind::spinning, "spinning"},
                                                             {SensorKind::solid_state, "solid_state"}}}};
bool from_string(const std::string& text, SensorKind* out);
std::string to_string(SensorKind kind);

/// What detect_sensor measured, and what it concluded.
struct SensorDetection {
  SensorKind kind = SensorKind::spinning;
  /// The fraction of the azimuth circle the scan covers: of kAzimuthSectors equal sectors about the
  /// sensor's vertical, those holding at least 1/20 of an even share of the scan's points
  double azimuth_coverage = 1.0;
};

/// Sectors of the azimuth circle detect_sensor counts (5° each).
inline constexpr int kAzimuthSectors = 72;
/// The line between the two kinds: between a third of the circle (the widest solid-state view) and half
/// of it (the narrowest rotating scanner) [fraction]
inline constexpr double kSpinningCoverage = 0.4;

/// The kind of sensor of a scan in its own frame: spinning when its points cover at least
/// kSpinningCoverage of the azimuth circle, solid_state otherwise. A spinning lidar covers all of it but
/// what its platform and the nearest walls hide, a rotating 2D scanner at least half; a solid-state one
/// its field of view, at most about 120°, a third (docs/odometry.md, "Which check applies to which sensor
/// and platform"). An empty scan is taken as spinning with coverage 0 (no evidence either way: the checks
/// of the kind that has them).
SensorDetection detect_sensor(const PointCloud& scan);

/// `declared` unless it is automatic, else what detect_sensor says of `scan`.
SensorDetection resolve_sensor(SensorKind declared, const PointCloud& scan);

}  // namespace sextant
