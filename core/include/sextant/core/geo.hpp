#pragma once
// GNSS positions (WGS84 latitude, longitude, ellipsoidal altitude) in metric frames, through
// GeographicLib (linked privately; no GeographicLib header here):
//  - a local ENU frame (x east, y north, z up) tangent at an origin fix (LocalCartesian);
//  - UTM/UPS (UTMUPS);
//  - KITTI-raw OXTS records (GNSS/INS) turned into 6D poses.
#include <array>
#include <filesystem>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "sextant/core/trajectory.hpp"

namespace sextant {

struct GeoFix {
  double latitude = 0.0;   ///< [deg], WGS84, north positive, in [−90, 90]
  double longitude = 0.0;  ///< [deg], east positive
  double altitude = 0.0;   ///< [m] above the WGS84 ellipsoid
};

/// x east, y north, z up [m] in the plane tangent at the origin fix.
class LocalEnu {
 public:
  /// std::invalid_argument for a non-finite origin or |latitude| > 90°.
  explicit LocalEnu(const GeoFix& origin);
  ~LocalEnu();
  LocalEnu(LocalEnu&&) noexcept;
  LocalEnu& operator=(LocalEnu&&) noexcept;

  const GeoFix& origin() const { return origin_; }
  Eigen::Vector3d to_enu(const GeoFix& fix) const;
  GeoFix to_geodetic(const Eigen::Vector3d& enu) const;

 private:
  struct Impl;
  GeoFix origin_;
  std::unique_ptr<Impl> impl_;
};

struct UtmCoordinate {
  int zone = 0;           ///< 1…60; 0 means UPS (polar)
  bool northern = true;   ///< hemisphere
  double easting = 0.0;   ///< [m]
  double northing = 0.0;  ///< [m]
};

/// The standard UTM zone (UPS near the poles); std::invalid_argument for an invalid fix.
UtmCoordinate to_utm(const GeoFix& fix);
/// Inverse of to_utm (altitude 0).
GeoFix from_utm(const UtmCoordinate& utm);

/// One KITTI-raw OXTS record: 30 space-separated numbers per line, in this order
/// (KITTI raw devkit, dataformat.txt):
///   0 lat [deg]  1 lon [deg]  2 alt [m]  3 roll [rad]  4 pitch [rad]  5 yaw [rad] (0 = east,
///   counter-clockwise)  6 vn  7 ve [m/s] (north, east)  8 vf  9 vl  10 vu [m/s] (forward, left, up)
///   11 ax 12 ay 13 az [m/s²] (x, y, z)  14 af 15 al 16 au [m/s²] (forward, left, up)
///   17 wx 18 wy 19 wz [rad/s]  20 wf 21 wl 22 wu [rad/s]  23 pos_accuracy [m]
///   24 vel_accuracy [m/s]  25 navstat  26 numsats  27 posmode  28 velmode  29 orimode.
struct OxtsRecord {
  static constexpr int kFieldCount = 30;
  GeoFix fix;
  double roll = 0.0, pitch = 0.0, yaw = 0.0;  ///< [rad]
  std::array<double, kFieldCount> fields{};   ///< every field, in file order
};

/// Every non-blank line of an OXTS file (KITTI raw stores one record per file, oxts/data/*.txt).
/// InputError naming line and problem for a malformed number or a wrong field count.
std::vector<OxtsRecord> read_oxts_file(const std::filesystem::path& file);
/// The records of a KITTI-raw `oxts` folder: the numbered files of `folder/data` (or of `folder`
/// itself), sorted by number, one record each.
std::vector<OxtsRecord> read_oxts_folder(const std::filesystem::path& folder);

/// World ← IMU poses: translation = ENU position with the origin at the first fix,
/// R = Rz(yaw)·Ry(pitch)·Rx(roll) as in the KITTI devkit (convertOxtsToPose, which uses a
/// Mercator projection instead of ENU). Stamps are the record index.
Trajectory oxts_to_poses(const std::vector<OxtsRecord>& records);

}  // namespace sextant
