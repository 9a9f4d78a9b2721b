#include "sextant/synth/settings.hpp"

#include <cmath>

#include <fmt/format.h>

#include "sextant/core/units.hpp"
#include "sextant/synth/route.hpp"
#include "sextant/synth/settings_fields.hpp"

namespace sextant::synth {
namespace {

/// Collects the first failed condition as the reason.
class Checker {
 public:
  explicit Checker(std::string* why) : why_(why) {}
  void require(bool ok, const std::string& what) {
    if (!ok && ok_) {
      ok_ = false;
      if (why_) *why_ = what;
    }
  }
  bool ok() const { return ok_; }

 private:
  std::string* why_;
  bool ok_ = true;
};

std::string format_value(double x) {
  return fmt::format("{}", x);
}
std::string format_value(int x) {
  return fmt::format("{}", x);
}
std::string format_value(const std::string& x) {
  return x;
}

}  // namespace

bool WorldSettings::valid(std::string* why) const {
  Checker c(why);
  c.require(block_length >= 30.0, "block_length must be at least 30 m");
  c.require(block_width >= 20.0, "block_width must be at least 20 m");
  c.require(border >= 10.0, "border must be at least 10 m");
  c.require(road_half_width > 1.0 && road_half_width < 0.25 * block_width,
            "road_half_width must be in (1 m, block_width/4)");
  c.require(ground_cell >= 0.5, "ground_cell must be at least 0.5 m");
  c.require(ground_amplitude >= 0.0, "ground_amplitude must not be negative");
  c.require(ground_wavelength > 10.0, "ground_wavelength must exceed 10 m");
  c.require(std::abs(ground_tilt) <= 0.1, "ground_tilt must be within ±0.1");
  c.require(kerb_height >= 0.0 && kerb_height < 0.5, "kerb_height must be in [0, 0.5) m");
  c.require(building_probability >= 0.0 && building_probability <= 1.0,
            "building_probability must be in [0, 1]");
  c.require(min_building_height >= 3.0, "min_building_height must be at least 3 m");
  c.require(max_building_height >= min_building_height, "max_building_height must be >= min_building_height");
  c.require(max_roof_pitch_deg >= 0.0 && max_roof_pitch_deg < 60.0, "max_roof_pitch_deg must be in [0, 60)");
  c.require(car_spacing >= 5.0, "car_spacing must be at least 5 m");
  c.require(pole_spacing >= 2.0, "pole_spacing must be at least 2 m");
  c.require(tree_spacing >= 3.0, "tree_spacing must be at least 3 m");
  c.require(bushes_per_lot >= 0, "bushes_per_lot must not be negative");
  c.require(foliage_porosity >= 0.0 && foliage_porosity < 1.0, "foliage_porosity must be in [0, 1)");
  c.require(foliage_penetration >= 0.0, "foliage_penetration must not be negative");
  c.require(grid_cell >= 0.5, "grid_cell must be at least 0.5 m");
  return c.ok();
}

bool TrajectorySettings::valid(std::string* why) const {
  Checker c(why);
  c.require(scans >= 1 && scans <= kMaxRouteScans, "scans must be in [1, " + std::to_string(kMaxRouteScans) +
                                                       "] (" + std::to_string(kMaxRouteScans) +
                                                       " puts a scan every ~1.3 cm along the route)");
  c.require(first_scans >= 0 && first_scans <= scans,
            "first_scans must be in [0, scans] (0 keeps the whole route; use scans to stretch it)");
  c.require(sensor_height > 0.2, "sensor_height must exceed 0.2 m");
  c.require(corner_radius >= 0.0 && corner_radius <= 14.0, "corner_radius must be in [0, 14] m");
  c.require(std::isfinite(corner_transition) && corner_transition >= 0.0 &&
                (corner_radius > 0.0 || corner_transition == 0.0),
            "corner_transition must be ≥ 0 m, and 0 without rounded corners (corner_radius 0)");
  c.require(sharp_turn_deg > 0.0 && sharp_turn_deg < 90.0, "sharp_turn_deg must be in (0, 90)");
  c.require(wheelbase > 0.0, "wheelbase must be positive");
  c.require(track > 0.0, "track must be positive");
  c.require(scan_period > 0.0, "scan_period must be positive");
  c.require(lateral_wander >= 0.0 && lateral_wander <= 2.0, "lateral_wander must be in [0, 2] m");
  c.require(platform == "car" || platform == "handheld", "platform must be car or handheld");
  c.require(sway_deg >= 0.0 && sway_deg <= 30.0, "sway_deg must be in [0, 30]");
  c.require(look_around_deg >= 0.0 && look_around_deg <= 90.0, "look_around_deg must be in [0, 90]");
  c.require(look_around_scans >= 2.0, "look_around_scans must be at least 2");
  return c.ok();
}

bool SensorSettings::valid(std::string* why) const {
  Checker c(why);
  c.require(yaw_steps >= 4, "yaw_steps must be at least 4");
  c.require(elevation_steps >= 2, "elevation_steps must be at least 2");
  c.require(elevation_min_deg >= -90.0 && elevation_min_deg < elevation_max_deg && elevation_max_deg <= 90.0,
            "elevation_min_deg must be below elevation_max_deg, both within [-90, 90]");
  c.require(min_range >= 0.0, "min_range must not be negative");
  c.require(max_range > min_range, "max_range must be positive and exceed min_range");
  c.require(max_range <= 32.7,
            "max_range must not exceed 32.7 m (the uos format reads 32.75 m as 'no return')");
  c.require(range_noise >= 0.0, "range_noise must not be negative");
  c.require(body_length >= 0.0, "body_length must not be negative");
  c.require(body_width >= 0.0, "body_width must not be negative");
  c.require(body_top < 0.0, "body_top must be below the scanner (negative)");
  c.require(pattern == "spinning" || pattern == "rosette", "pattern must be spinning or rosette");
  c.require(rosette_rays >= 1, "rosette_rays must be at least 1");
  c.require(fov_horizontal_deg > 0.0 && fov_horizontal_deg < 180.0, "fov_horizontal_deg must be in (0, 180)");
  c.require(fov_vertical_deg > 0.0 && fov_vertical_deg < 180.0, "fov_vertical_deg must be in (0, 180)");
  c.require(std::isfinite(sweep_period) && sweep_period >= 0.0,
            "sweep_period must be a finite number of seconds ≥ 0 (0: instantaneous scans)");
  return c.ok();
}

bool OdometrySettings::valid(std::string* why) const {
  Checker c(why);
  c.require(model == "thesis" || model == "gaussian" || model == "student_t",
            "model must be 'thesis', 'gaussian' or 'student_t'");
  c.require(sigma_forward >= 0.0, "sigma_forward must not be negative");
  c.require(sigma_lateral >= 0.0, "sigma_lateral must not be negative");
  c.require(sigma_heading_deg >= 0.0, "sigma_heading_deg must not be negative");
  c.require(outlier_probability >= 0.0 && outlier_probability <= 1.0,
            "outlier_probability must be in [0, 1]");
  c.require(outlier_scale >= 1.0, "outlier_scale must be at least 1");
  c.require(gaussian_translation >= 0.0, "gaussian_translation must not be negative");
  c.require(gaussian_heading_deg >= 0.0, "gaussian_heading_deg must not be negative");
  // ν ≤ 1 (Cauchy and heavier) has no mean, so the model could not be "zero mean"; NaN fails too.
  c.require(std::isfinite(student_t_dof) && student_t_dof > 1.0,
            "student_t_dof must be a finite number of degrees of freedom above 1 (ν ≤ 1 has no mean)");
  c.require(student_t_translation >= 0.0, "student_t_translation must not be negative");
  c.require(student_t_heading_deg >= 0.0, "student_t_heading_deg must not be negative");
  return c.ok();
}

bool GnssSettings::valid(std::string* why) const {
  Checker c(why);
  c.require(std::abs(origin_latitude) < 89.0, "origin_latitude must be within ±89°");
  c.require(std::abs(origin_longitude) <= 180.0, "origin_longitude must be within ±180°");
  c.require(sigma_horizontal >= 0.0, "sigma_horizontal must not be negative");
  c.require(sigma_vertical >= 0.0, "sigma_vertical must not be negative");
  c.require(sigma_attitude_deg >= 0.0, "sigma_attitude_deg must not be negative");
  return c.ok();
}

bool CampusSettings::valid(std::string* why) const {
  std::string reason;
  const auto check = [&](const char* name, bool ok) {
    if (!ok && why && why->empty()) *why = std::string(name) + "." + reason;
    return ok;
  };
  if (why) why->clear();
  // The first invalid part names the reason; the rest are not checked.
  const bool sections = check("world", world.valid(&reason)) &&
                        check("trajectory", trajectory.valid(&reason)) &&
                        check("sensor", sensor.valid(&reason)) &&
                        check("odometry", odometry.valid(&reason)) && check("gnss", gnss.valid(&reason));
  if (!sections) return false;
  // The campus' corners turn by a right angle; an eased one needs its tangent length on both ends of a
  // block side.
  reason = "corner_transition is too long: the eased corners do not fit on a block side";
  const double tangent =
      corner_tangent_length(trajectory.corner_radius, trajectory.corner_transition, 0.5 * kPi);
  if (trajectory.corner_transition > 0.0 &&
      !check("trajectory", 2.0 * tangent <= std::min(world.block_length, world.block_width)))
    return false;
  reason = "sweep_period must not exceed trajectory.scan_period (a sweep ends before the next scan starts)";
  return check("sensor", sensor.sweep_period <= trajectory.scan_period);
}

std::string campus_settings_yaml(const CampusSettings& settings, std::uint64_t seed) {
  CampusSettings copy = settings;
  std::string out = "# Synthetic campus: resolved settings (sextant synth)\n";
  out += fmt::format("seed: {}\n", seed);
  visit_sections(copy, [&out](const char* name, auto& section) {
    out += std::string(name) + ":\n";
    visit(section, [&out](const char* key, auto& field) {
      out += fmt::format("  {}: {}\n", key, format_value(field));
    });
  });
  return out;
}

std::uint64_t campus_hash(const CampusSettings& settings, std::uint64_t seed) {
  // FNV-1a over the canonical YAML text (shortest round-trip number formatting).
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const unsigned char ch : campus_settings_yaml(settings, seed)) {
    h ^= ch;
    h *= 0x100000001b3ULL;
  }
  return h;
}

}  // namespace sextant::synth
