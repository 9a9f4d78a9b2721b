#include "sextant/synth/settings.hpp"

#include <cmath>

#include <fmt/format.h>

#include "sextant/core/settings_reader.hpp"

namespace sextant::synth {
namespace {

// Each section's keys are listed once and visited for reading, writing and hashing.
template <class Visitor>
void visit(WorldSettings& s, Visitor&& v) {
  v("block_length", s.block_length);
  v("block_width", s.block_width);
  v("border", s.border);
  v("road_half_width", s.road_half_width);
  v("ground_cell", s.ground_cell);
  v("ground_amplitude", s.ground_amplitude);
  v("ground_wavelength", s.ground_wavelength);
  v("ground_tilt", s.ground_tilt);
  v("kerb_height", s.kerb_height);
  v("building_probability", s.building_probability);
  v("min_building_height", s.min_building_height);
  v("max_building_height", s.max_building_height);
  v("max_roof_pitch_deg", s.max_roof_pitch_deg);
  v("car_spacing", s.car_spacing);
  v("pole_spacing", s.pole_spacing);
  v("tree_spacing", s.tree_spacing);
  v("bushes_per_lot", s.bushes_per_lot);
  v("foliage_porosity", s.foliage_porosity);
  v("foliage_penetration", s.foliage_penetration);
  v("grid_cell", s.grid_cell);
}

template <class Visitor>
void visit(TrajectorySettings& s, Visitor&& v) {
  v("scans", s.scans);
  v("first_scans", s.first_scans);
  v("sensor_height", s.sensor_height);
  v("corner_radius", s.corner_radius);
  v("sharp_turn_deg", s.sharp_turn_deg);
  v("wheelbase", s.wheelbase);
  v("track", s.track);
  v("scan_period", s.scan_period);
  v("lateral_wander", s.lateral_wander);
}

template <class Visitor>
void visit(SensorSettings& s, Visitor&& v) {
  v("yaw_steps", s.yaw_steps);
  v("elevation_steps", s.elevation_steps);
  v("elevation_min_deg", s.elevation_min_deg);
  v("elevation_max_deg", s.elevation_max_deg);
  v("min_range", s.min_range);
  v("max_range", s.max_range);
  v("range_noise", s.range_noise);
  v("body_length", s.body_length);
  v("body_width", s.body_width);
  v("body_top", s.body_top);
}

template <class Visitor>
void visit(OdometrySettings& s, Visitor&& v) {
  v("model", s.model);
  v("bias_forward", s.bias_forward);
  v("bias_lateral", s.bias_lateral);
  v("bias_heading_deg", s.bias_heading_deg);
  v("sigma_forward", s.sigma_forward);
  v("sigma_lateral", s.sigma_lateral);
  v("sigma_heading_deg", s.sigma_heading_deg);
  v("outlier_probability", s.outlier_probability);
  v("outlier_scale", s.outlier_scale);
  v("gaussian_translation", s.gaussian_translation);
  v("gaussian_heading_deg", s.gaussian_heading_deg);
}

template <class Visitor>
void visit(GnssSettings& s, Visitor&& v) {
  v("origin_latitude", s.origin_latitude);
  v("origin_longitude", s.origin_longitude);
  v("origin_altitude", s.origin_altitude);
  v("sigma_horizontal", s.sigma_horizontal);
  v("sigma_vertical", s.sigma_vertical);
  v("sigma_attitude_deg", s.sigma_attitude_deg);
}

template <class Visitor>
void visit_sections(CampusSettings& s, Visitor&& v) {
  v("world", s.world);
  v("trajectory", s.trajectory);
  v("sensor", s.sensor);
  v("odometry", s.odometry);
  v("gnss", s.gnss);
}

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

template <class Section>
void read_section(SettingsReader& in, const std::string& key, Section& section) {
  SettingsReader sub(in.child(key), in.file());
  visit(section, [&sub](const char* name, auto& field) { sub.read(name, field); });
  sub.finish();
  std::string why;
  if (!section.valid(&why)) {
    // Name the offending key when the reason starts with it.
    const std::string bad = why.substr(0, why.find(' '));
    sub.fail(sub.has(bad) ? bad : "", key + "." + why);
  }
}

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
  c.require(scans >= 1, "scans must be at least 1");
  c.require(first_scans >= 0 && first_scans <= scans,
            "first_scans must be in [0, scans] (0 keeps the whole route; use scans to stretch it)");
  c.require(sensor_height > 0.2, "sensor_height must exceed 0.2 m");
  c.require(corner_radius >= 0.0 && corner_radius <= 14.0, "corner_radius must be in [0, 14] m");
  c.require(sharp_turn_deg > 0.0 && sharp_turn_deg < 90.0, "sharp_turn_deg must be in (0, 90)");
  c.require(wheelbase > 0.0, "wheelbase must be positive");
  c.require(track > 0.0, "track must be positive");
  c.require(scan_period > 0.0, "scan_period must be positive");
  c.require(lateral_wander >= 0.0 && lateral_wander <= 2.0, "lateral_wander must be in [0, 2] m");
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
  return c.ok();
}

bool OdometrySettings::valid(std::string* why) const {
  Checker c(why);
  c.require(model == "thesis" || model == "gaussian", "model must be 'thesis' or 'gaussian'");
  c.require(sigma_forward >= 0.0, "sigma_forward must not be negative");
  c.require(sigma_lateral >= 0.0, "sigma_lateral must not be negative");
  c.require(sigma_heading_deg >= 0.0, "sigma_heading_deg must not be negative");
  c.require(outlier_probability >= 0.0 && outlier_probability <= 1.0,
            "outlier_probability must be in [0, 1]");
  c.require(outlier_scale >= 1.0, "outlier_scale must be at least 1");
  c.require(gaussian_translation >= 0.0, "gaussian_translation must not be negative");
  c.require(gaussian_heading_deg >= 0.0, "gaussian_heading_deg must not be negative");
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
  const bool ok = check("world", world.valid(&reason)) & check("trajectory", trajectory.valid(&reason)) &
                  check("sensor", sensor.valid(&reason)) & check("odometry", odometry.valid(&reason)) &
                  check("gnss", gnss.valid(&reason));
  return ok;
}

CampusSettings read_campus_settings(const YAML::Node& node, const std::string& file, std::uint64_t* seed) {
  CampusSettings settings;
  SettingsReader in(node, file);
  if (seed) in.read("seed", *seed);
  visit_sections(settings, [&in](const char* name, auto& section) { read_section(in, name, section); });
  in.finish();
  return settings;
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
