#pragma once
// A coarse campus for fast tests: the full world and route, few scans, a sparse sensor.
#include "sextant/synth/settings.hpp"

namespace sextant::synth::test {

inline CampusSettings small_campus(int scans = 8) {
  CampusSettings s;
  s.trajectory.scans = scans;
  s.sensor.yaw_steps = 48;
  s.sensor.elevation_steps = 40;
  return s;
}

}  // namespace sextant::synth::test
