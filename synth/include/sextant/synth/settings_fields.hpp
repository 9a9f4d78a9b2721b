#pragma once
// The keys of the campus settings, listed once: visit(section, v) calls v(key, field) for every
// field of a section, visit_sections(settings, v) calls v(name, section) for every section. Writing
// (campus_settings_yaml), hashing and reading from YAML (synth/yaml.hpp) all walk them.
#include "sextant/synth/settings.hpp"

namespace sextant::synth {

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
  v("corner_transition", s.corner_transition);
  v("sharp_turn_deg", s.sharp_turn_deg);
  v("wheelbase", s.wheelbase);
  v("track", s.track);
  v("scan_period", s.scan_period);
  v("lateral_wander", s.lateral_wander);
  v("platform", s.platform);
  v("sway_deg", s.sway_deg);
  v("look_around_deg", s.look_around_deg);
  v("look_around_scans", s.look_around_scans);
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
  v("pattern", s.pattern);
  v("rosette_rays", s.rosette_rays);
  v("fov_horizontal_deg", s.fov_horizontal_deg);
  v("fov_vertical_deg", s.fov_vertical_deg);
  v("sweep_period", s.sweep_period);
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
  v("student_t_dof", s.student_t_dof);
  v("student_t_translation", s.student_t_translation);
  v("student_t_heading_deg", s.student_t_heading_deg);
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

}  // namespace sextant::synth
