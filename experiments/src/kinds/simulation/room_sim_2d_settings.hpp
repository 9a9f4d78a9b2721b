#pragma once
// The 2D room simulation's settings from YAML (the `room:` map of a simulation config, room.cpp).
#include <string>

#include <yaml-cpp/yaml.h>

#include "simulation/room_sim_2d.hpp"

namespace sextant {

/// Keys: the field names of RoomSim2dSettings.
RoomSim2dSettings read_room_sim_2d_settings(const YAML::Node& node, const std::string& file);

/// room_sim_matcher_settings() as ML-NDT's YAML keys: `dof: [x, y, yaw]` and three layers.
YAML::Node room_sim_matcher_defaults();

}  // namespace sextant
