// Plane SLAM on the synthetic campus with its true plane landmarks, true data association and
// ground truth (issue 6, "Done when"): EKF, UKF and CKF, driven by the campus' 2D odometry,
// must end with a position error well below the odometry's. Observations are the true planes
// seen from the true pose (eq. 4.64) plus Gaussian noise matching R; no extraction, no
// semantic association (plane_slam_campus_test.cpp covers those).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>

#include "plane_world.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/filters/filter.hpp"
#include "sextant/filters/yaml.hpp"
#include "sextant/synth/campus.hpp"

namespace sextant {
namespace {

constexpr std::size_t kScans = 50;  // the first kScans poses of the thesis-spaced route
// A landmark is observed when a scan has this many points on it. The reduced sensor below casts
// 9000 rays (default 28800), so 100 points here are about 320 at the default density. Measured
// with 200 here (≈ 640 at the default density) fewer façades across the street are kept and the
// filters end at 0.27–0.37 of odometry's 3D error and 0.27–0.33 of its xy error: below, not
// "well below" — stated, not asserted.
constexpr std::size_t kMinPoints = 100;
constexpr double kSigmaNormal = 0.01;    // observation noise of each normal component [-]
constexpr double kSigmaDistance = 0.05;  // observation noise of d [m]

const synth::Campus& campus() {
  static const synth::Campus c = [] {
    synth::CampusSettings s;
    s.trajectory.scans = 468;        // thesis spacing between scans; the test uses the first kScans
    s.odometry.model = "gaussian";   // zero mean, 20 cm and 1° per relative motion (figs 5.32–5.34)
    s.sensor.yaw_steps = 90;         // 4° between scan lines (default 2°)
    s.sensor.elevation_steps = 100;  // 1° between rays (default 0.625°)
    return synth::generate_campus(s, 11);
  }();
  return c;
}

/// The campus as a test::PlaneWorld: caller ids number the true landmarks in order of first
/// sighting, so the first scan's landmarks are 0..m−1 as test::start_plane_slam expects.
test::PlaneWorld campus_world(std::uint64_t seed) {
  const synth::Campus& c = campus();
  test::PlaneWorld w;
  // Q (eq. 4.72, control noise): the gaussian odometry's 20 cm and 1° per step in x, y, γ; the
  // 2D odometry reports δz = δα = δβ = 0 while the terrain changes them, so those get the
  // spread of the ground-following motion (a few cm and tenths of a degree per step).
  const double deg = M_PI / 180.0;
  w.Q = (Eigen::VectorXd(6) << 0.2, 0.2, 0.1, 1.0 * deg, 1.0 * deg, 1.0 * deg)
            .finished()
            .array()
            .square()
            .matrix()
            .asDiagonal();
  w.R = Eigen::Vector4d(kSigmaNormal * kSigmaNormal, kSigmaNormal * kSigmaNormal, kSigmaNormal * kSigmaNormal,
                        kSigmaDistance * kSigmaDistance)
            .asDiagonal();
  Rng rng(seed);
  const PlaneSlamModel model;
  std::map<int, int> caller_id;  // true landmark id → caller id
  auto observe = [&](std::size_t k) {
    const synth::SimulatedScan scan = c.scan(k);
    std::vector<SlamObservation> out;
    for (const synth::LandmarkVisibility& v : scan.visible) {
      if (v.points < kMinPoints) continue;
      const synth::Landmark& l = c.world->landmarks[static_cast<std::size_t>(v.landmark)];
      const auto [it, fresh] = caller_id.emplace(l.id, static_cast<int>(caller_id.size()));
      if (fresh) w.planes.emplace_back(l.normal.x(), l.normal.y(), l.normal.z(), l.d);
      // z = (Rᵀnᵂ, dᵂ − nᵂ·t) (eq. 4.64) from the true pose, with the noise of make_plane_world.
      Eigen::VectorXd z = model.observe(w.truth[k].vector(), w.planes[static_cast<std::size_t>(it->second)]);
      z.head<3>() += kSigmaNormal * Eigen::Vector3d(rng.normal(), rng.normal(), rng.normal());
      z.head<3>().normalize();
      z[3] += kSigmaDistance * rng.normal();
      out.push_back({z, it->second});
    }
    return out;
  };
  for (std::size_t k = 0; k < kScans; ++k) w.truth.push_back(to_pose6(c.ground_truth[k]));
  for (const SlamObservation& o : observe(0)) w.first_observations.push_back(o.z);
  // Dead reckoning from the true start with the same increments the filters get (eq. 4.72).
  w.odometry.push_back(w.truth[0]);
  for (std::size_t k = 0; k + 1 < kScans; ++k) {
    const Vector6d u = odometry_increment(to_pose6(c.odometry[k]), to_pose6(c.odometry[k + 1]));
    w.steps.push_back({u, observe(k + 1)});
    w.odometry.push_back(Pose6::from_vector(model.process(w.odometry.back().vector(), u)));
  }
  return w;
}

double xy_error(const Eigen::VectorXd& pose, const Pose6& truth) {
  return (pose.head<2>() - Eigen::Vector2d(truth.x, truth.y)).norm();
}

// Every landmark kept on this stretch is a vertical façade (no roof reaches kMinPoints), so z is
// not observed directly: the filters get it from the vehicle model (4.72) through the attitude,
// whose roll and pitch the façade normals do observe, while the 2D odometry keeps the start
// attitude. Both the 3D and the xy (fully observed) errors are asserted.
TEST(PlaneSlamTrueLandmarks, FiltersEndWellBelowOdometryOnCampus) {
  const test::PlaneWorld world = campus_world(3);
  const Pose6& odometry_end = world.odometry.back();
  const double odometry_error = test::position_error(odometry_end.vector(), world.truth.back());
  const double odometry_xy = xy_error(odometry_end.vector(), world.truth.back());
  std::size_t observations = 0;
  for (const SlamStepInput& s : world.steps) observations += s.observations.size();
  std::printf(
      "[plane-slam-true] campus seed 11, %zu scans, %zu true landmarks, %zu observations (>= %zu points)\n",
      kScans, world.planes.size(), observations, kMinPoints);
  std::printf("[plane-slam-true] odometry  final position error %.3f m (xy %.3f m)\n", odometry_error,
              odometry_xy);
  auto model = std::make_shared<PlaneSlamModel>();
  for (const std::string name : {"ekf", "ukf", "ckf"}) {
    auto filter = make_filter(name, model);
    const auto known = test::start_plane_slam(*filter, world);
    const SlamRunResult run = run_slam(*filter, world.steps, world.Q, world.R, {}, known);
    double worst = 0.0;
    for (std::size_t k = 0; k < run.steps.size(); ++k)
      worst = std::max(worst, test::position_error(run.steps[k].pose, world.truth[k + 1]));
    const double final_error = test::position_error(run.steps.back().pose, world.truth.back());
    std::printf(
        "[plane-slam-true] %-9s final position error %.3f m (xy %.3f m, worst along the run %.3f m), ratio "
        "to "
        "odometry %.3f, failed steps %zu\n",
        name.c_str(), final_error, xy_error(run.steps.back().pose, world.truth.back()), worst,
        final_error / odometry_error, run.failed_steps);
    EXPECT_EQ(run.failed_steps, 0u) << name;
    EXPECT_LT(final_error, 0.3 * odometry_error) << name;
    EXPECT_LT(xy_error(run.steps.back().pose, world.truth.back()), 0.3 * odometry_xy) << name;
    EXPECT_EQ(filter->num_landmarks(), static_cast<int>(world.planes.size())) << name;
  }
}

}  // namespace
}  // namespace sextant
