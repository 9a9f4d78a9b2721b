#pragma once
// Every parameter of the synthetic campus, with the thesis-like defaults (docs/design.md, "The
// synthetic campus"; docs/experiments.md, "How to read this page"). World frame: x east,
// y north, z up, metres.
#include <cstdint>
#include <string>

namespace sextant::synth {

struct WorldSettings {
  double block_length = 80.0;         ///< east–west length of a city block, between road centre lines [m]
  double block_width = 30.0;          ///< north–south width of a city block [m]
  double border = 34.0;               ///< built-up strip around the 2×2 blocks [m]
  double road_half_width = 4.0;       ///< kerb offset from the road centre line [m]
  double ground_cell = 4.0;           ///< ground mesh spacing [m]
  double ground_amplitude = 1.2;      ///< amplitude of the rolling ground [m]
  double ground_wavelength = 110.0;   ///< wavelength of the rolling ground [m]
  double ground_tilt = 0.012;         ///< overall slope of the ground (rise/run) [-]
  double kerb_height = 0.12;          ///< [m]
  double building_probability = 0.8;  ///< chance that a lot holds a building (else a wall and clutter) [-]
  double min_building_height = 6.0;   ///< [m]
  double max_building_height = 18.0;  ///< [m]
  double max_roof_pitch_deg = 35.0;   ///< [deg]
  double car_spacing = 14.0;          ///< mean spacing of parked cars along a road side [m]
  double pole_spacing = 25.0;         ///< mean spacing of poles along a road side [m]
  double tree_spacing = 16.0;         ///< mean spacing of trees along a road side [m]
  int bushes_per_lot = 3;             ///< bushes scattered on each lot [-]
  double foliage_porosity = 0.35;     ///< chance that a ray passes through a foliage blob [-]
  double foliage_penetration = 0.6;   ///< depth a ray may enter foliage before returning [m]
  double grid_cell = 4.0;             ///< cell size of the ray-casting grid [m]

  bool valid(std::string* why) const;
};

/// The most scans the route may be divided into: a scan every ~1.3 cm of its 1.3 km, closer than any
/// lidar records; more would only exhaust the memory (every pose is generated).
inline constexpr int kMaxRouteScans = 100000;

struct TrajectorySettings {
  int scans = 468;      ///< stop-and-go scan poses the whole route is divided into (sets the spacing), ≤
                        ///< kMaxRouteScans [-]
  int first_scans = 0;  ///< keep only the first N of those poses (0 = all; ≤ scans) [-]
  double sensor_height = 1.1;  ///< scanner above the ground contact [m]
  double corner_radius = 9.0;  ///< radius of the rounded corners [m]
  /// Length of the clothoid easing each corner's arc in and out, its curvature growing linearly from 0 to
  /// 1 / corner_radius (a road's transition curve: the yaw rate ramps up, the lateral jerk is bounded);
  /// 0: the arcs start at once (a yaw rate that jumps) [m]
  double corner_transition = 0.0;
  double sharp_turn_deg = 51.5;  ///< the one turn on the spot, between scans 3 and 4 by default [deg]
  double wheelbase = 1.2;        ///< distance used to sample the ground for pitch [m]
  double track = 0.8;            ///< distance used to sample the ground for roll [m]
  double scan_period = 10.0;     ///< time between stop-and-go scans [s]
  double lateral_wander = 0.6;   ///< amplitude of the slow sideways wander on the road [m]
  /// "car": the sensor stands level on the terrain, facing the way it goes; "handheld": carried on foot,
  /// it sways in roll and pitch and looks around in yaw about the way it goes (a person's gait and gaze:
  /// handheld_sway in route.hpp)
  std::string platform = "car";
  double sway_deg = 3.0;            ///< handheld: amplitude of the roll and pitch sway [deg]
  double look_around_deg = 40.0;    ///< handheld: amplitude of the yaw swing about the heading [deg]
  double look_around_scans = 23.0;  ///< handheld: period of that swing [scans]

  bool valid(std::string* why) const;
};

struct SensorSettings {
  int yaw_steps = 180;               ///< scanner positions per turn about the vertical axis [-]
  int elevation_steps = 160;         ///< rays per 2D scan line [-]
  double elevation_min_deg = -50.0;  ///< lowest ray of a scan line [deg]
  double elevation_max_deg = 50.0;   ///< highest ray of a scan line [deg]
  double min_range = 0.3;            ///< returns closer than this are dropped [m]
  double max_range = 32.0;    ///< no return beyond this; ≤ 32.7 m (uos stores 32.75 m as "no return") [m]
  double range_noise = 0.01;  ///< standard deviation of the Gaussian range noise [m]
  double body_length = 1.0;   ///< vehicle body below the scanner, causing self-hits [m]
  double body_width = 0.7;    ///< [m]
  double body_top = -0.5;     ///< body top relative to the scanner [m]
  /// "spinning": the scan lines above, turned about the vertical; "rosette": a solid-state lidar's
  /// non-repetitive rosette over a fixed field of view facing x (a Livox Avia's, by default), which
  /// draws another part of the rosette at every scan (simulate_scan)
  std::string pattern = "spinning";
  int rosette_rays = 6000;           ///< rosette: rays per scan [-]
  double fov_horizontal_deg = 70.4;  ///< rosette: field of view about the vertical [deg]
  double fov_vertical_deg = 77.2;    ///< rosette: field of view in elevation [deg]
  /// How long one scan's sweep takes [s]: each ray is cast at its own time along it (the azimuth's
  /// fraction of the turn, or the rosette's fraction of its rays) from where the moving sensor then is,
  /// and its point carries that time (PointCloud::time, from the scan's stamp, the sweep's start). 0: an
  /// instantaneous scan, every ray from the scan's pose (no times). At most trajectory.scan_period
  double sweep_period = 0.0;

  bool valid(std::string* why) const;
};

/// 2D odometry (x, y, heading) error per relative motion between consecutive scans. The
/// "thesis" model reproduces table 5.1 (bias + heavy tails); "gaussian" the simulated
/// odometry of figs 5.32–5.34 (zero mean, 20 cm and 1° per relative motion); "student_t" a
/// zero-mean heavy-tailed alternative (an extension, issue 27): each component scale · t_ν, with
/// t_ν Student's t of ν = student_t_dof degrees of freedom (variance ν/(ν−2) · scale² for ν > 2).
struct OdometrySettings {
  std::string model = "thesis";        ///< "thesis", "gaussian" or "student_t"
  double bias_forward = 0.17;          ///< thesis: mean forward error per step [m]
  double bias_lateral = -0.775;        ///< thesis: mean sideways error per step [m]
  double bias_heading_deg = 0.5;       ///< thesis: mean heading error per step [deg]
  double sigma_forward = 0.105;        ///< thesis: core standard deviation [m]
  double sigma_lateral = 0.19;         ///< thesis: core standard deviation [m]
  double sigma_heading_deg = 0.51;     ///< thesis: core standard deviation [deg]
  double outlier_probability = 0.04;   ///< thesis: chance of a heavy-tailed step [-]
  double outlier_scale = 3.5;          ///< thesis: standard-deviation factor of those steps [-]
  double gaussian_translation = 0.20;  ///< gaussian: std of each translation component [m]
  double gaussian_heading_deg = 1.0;   ///< gaussian: std of the heading [deg]
  double student_t_dof = 3.0;          ///< student_t: degrees of freedom ν > 1 (a mean exists) [-]
  double student_t_translation = 0.2;  ///< student_t: scale of each translation component [m]
  double student_t_heading_deg = 1.0;  ///< student_t: scale of the heading [deg]

  bool valid(std::string* why) const;
};

struct GnssSettings {
  double origin_latitude = 52.38;   ///< geodetic origin of the world frame [deg]
  double origin_longitude = 9.72;   ///< [deg]
  double origin_altitude = 55.0;    ///< [m] above the WGS84 ellipsoid
  double sigma_horizontal = 0.3;    ///< [m]
  double sigma_vertical = 0.6;      ///< [m]
  double sigma_attitude_deg = 0.2;  ///< [deg]

  bool valid(std::string* why) const;
};

struct CampusSettings {
  WorldSettings world;
  TrajectorySettings trajectory;
  SensorSettings sensor;
  OdometrySettings odometry;
  GnssSettings gnss;

  bool valid(std::string* why) const;
};

/// The resolved settings (and seed) as YAML text, readable by read_campus_settings (synth/yaml.hpp).
std::string campus_settings_yaml(const CampusSettings& settings, std::uint64_t seed);

/// A stable 64-bit hash of the settings and seed (names the cache folder).
std::uint64_t campus_hash(const CampusSettings& settings, std::uint64_t seed);

}  // namespace sextant::synth
