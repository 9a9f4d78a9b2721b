// The 2D room simulation's settings from YAML (room_sim_2d_settings.hpp).
#include "simulation/room_sim_2d_settings.hpp"

#include "sextant/core/settings_reader.hpp"

namespace sextant {

RoomSim2dSettings read_room_sim_2d_settings(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  RoomSim2dSettings s;
  in.read("room_length", s.room_length);
  in.read("room_width", s.room_width);
  in.read("circle_x", s.circle_x);
  in.read("circle_y", s.circle_y);
  in.read("circle_radius", s.circle_radius);
  in.read("beams", s.beams);
  in.read("max_range", s.max_range);
  in.read("range_noise", s.range_noise);
  in.read("scan_every", s.scan_every);
  in.read("speed", s.speed);
  in.read("dt", s.dt);
  in.read("wheelbase", s.wheelbase);
  in.read("max_steer", s.max_steer);
  in.read("max_steer_rate", s.max_steer_rate);
  in.read("loop_length", s.loop_length);
  in.read("loop_width", s.loop_width);
  in.read("waypoint_radius", s.waypoint_radius);
  in.read("loops", s.loops);
  in.read("max_steps", s.max_steps);
  in.read("sigma_speed", s.sigma_speed);
  in.read("sigma_steer", s.sigma_steer);
  in.read("bias_speed", s.bias_speed);
  in.read("bias_steer", s.bias_steer);
  in.read("initial_sigma", s.initial_sigma);
  in.read("measurement_noise_scale", s.measurement_noise_scale);
  in.finish();
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
  return s;
}

YAML::Node room_sim_matcher_defaults() {
  return YAML::Load("{dof: [x, y, yaw], layers: 3}");
}

}  // namespace sextant
