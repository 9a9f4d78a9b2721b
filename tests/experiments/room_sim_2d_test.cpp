// E8 (§5.1.3.1): the 2D room simulation with ML-NDT (3-DOF mask) feeding the Ackermann EKF.
// The estimate must track the truth far better than dead reckoning of the same noisy controls.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "sextant/core/error.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/matchers/yaml.hpp"
#include "simulation/room_sim_2d_settings.hpp"

namespace sextant {
namespace {

double position_error(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return (a - b).head<2>().norm();
}

TEST(RoomSim2d, ScanSeesWallsAndCircle) {
  RoomSim2dSettings s;
  s.range_noise = 0.0;
  Rng rng(1);
  // From (−5, 0) heading +x: beam 0 hits the circle at x = −1.5, beam 180 (−x) the wall at −10.
  const PointCloud scan = simulate_room_scan(s, Eigen::Vector3d(-5.0, 0.0, 0.0), rng);
  ASSERT_EQ(scan.size(), static_cast<std::size_t>(s.beams));
  EXPECT_NEAR(scan[0].x(), 3.5f, 1e-5f);
  EXPECT_NEAR(scan[180].x(), -5.0f, 1e-5f);
  EXPECT_NEAR(scan[90].y(), 7.0f, 1e-5f);  // wall at y = 7
  for (const auto& p : scan.points()) EXPECT_EQ(p.z(), 0.f);
}

TEST(RoomSim2d, SettingsFromYaml) {
  const RoomSim2dSettings s = read_room_sim_2d_settings(YAML::Load("{beams: 200, loops: 1}"), "t.yaml");
  EXPECT_EQ(s.beams, 200);
  EXPECT_EQ(s.loops, 1);
  EXPECT_THROW(read_room_sim_2d_settings(YAML::Load("{beam: 200}"), "t.yaml"), InputError);
  EXPECT_THROW(read_room_sim_2d_settings(YAML::Load("{circle_radius: 9}"), "t.yaml"), InputError);
}

TEST(RoomSim2d, EkfWithMlndtTracksTheTruth) {
  RoomSim2dSettings s;  // two loops, 360 beams, a scan every second
  auto matcher = make_matcher("mlndt", room_sim_matcher_defaults());
  Rng rng(7);
  const RoomSim2dRun run = run_room_sim_2d(s, *matcher, rng);
  ASSERT_GT(run.steps.size(), 20u);
  ASSERT_EQ(run.truth_path.size(), run.controls);  // the true pose after every control
  EXPECT_EQ(run.truth_path[static_cast<std::size_t>(std::lround(s.scan_every / s.dt)) - 1],
            run.steps[1].truth);

  double sq_est = 0.0, sq_odo = 0.0, max_heading = 0.0;
  for (const RoomSimStep& step : run.steps) {
    sq_est += std::pow(position_error(step.estimate, step.truth), 2);
    sq_odo += std::pow(position_error(step.odometry, step.truth), 2);
    max_heading = std::max(max_heading, std::abs(wrap_angle(step.estimate[2] - step.truth[2])));
    // The vehicle stays inside the room and outside the circle.
    EXPECT_LT(std::abs(step.truth[0]), 0.5 * s.room_length);
    EXPECT_LT(std::abs(step.truth[1]), 0.5 * s.room_width);
    EXPECT_GT(step.truth.head<2>().norm(), s.circle_radius);
  }
  std::map<std::string, int> statuses;
  double xi_error = 0.0, xi_sigma = 0.0;  // matcher translation error vs the √R it claims
  for (std::size_t k = 1; k < run.steps.size(); ++k) {
    const RoomSimStep& step = run.steps[k];
    ++statuses[to_string(step.status)];
    if (step.status != RoomSimStatus::kUpdated) continue;
    xi_error += (step.xi_measured - step.xi_true).head<2>().norm() / static_cast<double>(run.updates);
    xi_sigma += std::sqrt(step.R.topLeftCorner<2, 2>().trace()) / static_cast<double>(run.updates);
  }
  for (const auto& [name, count] : statuses)
    std::printf("[room-sim-2d] status %s: %d\n", name.c_str(), count);
  std::printf("[room-sim-2d] mean matcher translation error %.4f m, mean sqrt(trace R_xy) %.4f m\n", xi_error,
              xi_sigma);
  const double n = static_cast<double>(run.steps.size());
  const double rms_est = std::sqrt(sq_est / n), rms_odo = std::sqrt(sq_odo / n);
  const double final_est = position_error(run.steps.back().estimate, run.steps.back().truth);
  const double final_odo = position_error(run.steps.back().odometry, run.steps.back().truth);
  std::printf(
      "[room-sim-2d] %zu scans, %zu updates: EKF+ML-NDT final %.3f m, RMS %.3f m, max heading error %.4f "
      "rad; "
      "dead reckoning final %.3f m, RMS %.3f m\n",
      run.steps.size(), run.updates, final_est, rms_est, max_heading, final_odo, rms_odo);
  EXPECT_GE(run.updates + 2, run.steps.size() - 1);  // at most two failed matches
  EXPECT_LT(final_est, 0.2 * final_odo);
  EXPECT_LT(rms_est, 0.2 * rms_odo);
  EXPECT_LT(max_heading, 0.05);
}

}  // namespace
}  // namespace sextant
