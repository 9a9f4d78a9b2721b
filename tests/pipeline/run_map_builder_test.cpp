// The run's map as the faces build it (pipeline/run_map_builder.hpp) on the built-in campus:
// run_odometry hands every scan with its final pose to its observer without changing any result, the
// map built as the run goes is the map of the scans at the run's poses, a map built after the run
// takes the poses it is given (the loop-closed ones), and scans of untrusted steps go in unless left out.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "sextant/core/error.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/pipeline/dataset_argument.hpp"
#include "sextant/pipeline/run_map_builder.hpp"

namespace sextant {
namespace {

constexpr std::size_t kFirst = 20, kScans = 8;

const Dataset& campus() {
  static const std::unique_ptr<Dataset> dataset = open_builtin_campus(1);
  return *dataset;
}

bool same_bits(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return a.matrix() == b.matrix();
}

bool same_cloud(const PointCloud& a, const PointCloud& b) {
  return a.points() == b.points() && a.intensity() == b.intensity();
}

/// The map of scans first + k at poses[k], built here scan by scan.
PointCloud map_by_hand(double voxel, const std::vector<Eigen::Isometry3d>& poses,
                       const std::vector<bool>& leave_out = {}) {
  RunMap map(voxel);
  for (std::size_t k = 0; k < poses.size(); ++k)
    if (leave_out.empty() || !leave_out[k]) map.add(load_sequence_scan(campus(), kFirst + k, 0.0), poses[k]);
  return map.cloud();
}

struct Seen {
  std::size_t index;
  Eigen::Isometry3d pose;
  std::size_t points;
  bool has_step;
  Eigen::Isometry3d step;
};

// Both of run_odometry's paths: the parallel one (odometry guess, scan-to-scan) and the sequential one.
TEST(RunMapObserver, SeesEveryScanInOrderWithItsFinalPoseAndChangesNothing) {
  for (const bool parallel : {true, false}) {
    SCOPED_TRACE(parallel ? "parallel" : "sequential");
    OdometrySettings s;
    s.guess = parallel ? OdometryGuess::odometry : OdometryGuess::constant_velocity;
    s.map = parallel ? OdometryMap::scan : OdometryMap::local_map;
    s.min_range = 2.0;
    const OdometryResult alone = run_odometry(campus(), s, kFirst, kScans);
    std::vector<Seen> seen;
    const OdometryResult watched =
        run_odometry(campus(), s, kFirst, kScans, {}, [&](const RegisteredScan& r) {
          seen.push_back({r.index, r.world_from_scan, r.scan->size(), r.step != nullptr,
                          r.step ? r.step->relative : Eigen::Isometry3d::Identity()});
          EXPECT_EQ(r.scan->points(), load_sequence_scan(campus(), kFirst + r.index, s.min_range).points())
              << "the whole scan as the chain read it, scan " << r.index;
        });
    ASSERT_EQ(watched.poses.size(), kScans);
    ASSERT_EQ(seen.size(), kScans);
    for (std::size_t k = 0; k < kScans; ++k) {
      EXPECT_TRUE(same_bits(watched.poses[k], alone.poses[k])) << "the observer changed pose " << k;
      EXPECT_EQ(seen[k].index, k);
      EXPECT_TRUE(same_bits(seen[k].pose, watched.poses[k])) << "pose " << k;
      EXPECT_EQ(seen[k].has_step, k > 0);
      if (k > 0) {
        EXPECT_TRUE(same_bits(seen[k].step, watched.steps[k - 1].relative)) << k;
      }
    }
  }
}

TEST(RunMapBuilder, TheMapBuiltAsTheRunGoesIsTheMapOfItsScansAtItsPoses) {
  RunMapBuilder builder(RunMapSettings{});
  const OdometryResult r = run_odometry(campus(), OdometrySettings{}, kFirst, kScans, {}, builder.observer());
  const RunMapSummary summary = builder.summary();
  // The default voxel comes from the run's first scan.
  const PointCloud first = load_sequence_scan(campus(), kFirst, 0.0);
  EXPECT_TRUE(summary.default_voxel);
  EXPECT_DOUBLE_EQ(summary.voxel, default_map_voxel_size(first));
  EXPECT_DOUBLE_EQ(summary.median_range, scan_median_range(first));
  EXPECT_NE(summary.voxel_origin().find("median range"), std::string::npos) << summary.voxel_origin();
  EXPECT_EQ(summary.scans, kScans);
  EXPECT_EQ(summary.scans_left_out, 0u);
  const PointCloud map = builder.map().cloud();
  EXPECT_EQ(summary.points, map.size());
  EXPECT_TRUE(same_cloud(map, map_by_hand(summary.voxel, r.poses)));
  // After the run, from the same poses, the same map.
  const RunMapBuilder after = build_run_map(campus(), kFirst, r.poses, r.steps, 0.0, RunMapSettings{});
  EXPECT_TRUE(same_cloud(after.map().cloud(), map));
  // Fewer points than the scans hold: what several scans saw is one point per voxel (the campus' 5 cm
  // voxel keeps 75 % of them).
  std::size_t points = 0;
  for (std::size_t k = 0; k < kScans; ++k) points += campus().scan(kFirst + k).size();
  EXPECT_LT(map.size(), points * 9 / 10) << points;
}

// With --loop-closure the poses change after the run: the map is built from the ones it is given.
TEST(RunMapBuilder, AMapBuiltAfterTheRunTakesThePosesItIsGiven) {
  const OdometryResult r = run_odometry(campus(), OdometrySettings{}, kFirst, kScans);
  std::vector<Eigen::Isometry3d> closed = r.poses;
  for (Eigen::Isometry3d& pose : closed) pose.pretranslate(Eigen::Vector3d(0.0, 0.0, 1.0));  // 1 m up
  RunMapSettings settings;
  settings.voxel = 0.25;
  const PointCloud chained = build_run_map(campus(), kFirst, r.poses, r.steps, 0.0, settings).map().cloud();
  const PointCloud moved = build_run_map(campus(), kFirst, closed, r.steps, 0.0, settings).map().cloud();
  EXPECT_TRUE(same_cloud(moved, map_by_hand(0.25, closed)));
  const auto mean_z = [](const PointCloud& c) {
    double z = 0.0;
    for (const Eigen::Vector3f& p : c.points()) z += p.z();
    return z / static_cast<double>(c.size());
  };
  // 1 m up, to within what moving the points across the voxels' boundaries changes of the centroids.
  EXPECT_NEAR(mean_z(moved) - mean_z(chained), 1.0, 0.02);
}

TEST(RunMapBuilder, ScansOfUntrustedStepsGoInUnlessLeftOut) {
  const OdometryResult r = run_odometry(campus(), OdometrySettings{}, kFirst, kScans);
  std::vector<OdometryStep> steps = r.steps;
  for (const OdometryStep& step : steps) ASSERT_TRUE(step.trusted());
  steps[2].quality.trust = Trust::kSuspect;     // places scan 3
  steps[5].quality.trust = Trust::kLowOverlap;  // places scan 6
  RunMapSettings settings;
  settings.voxel = 0.3;
  const RunMapBuilder all = build_run_map(campus(), kFirst, r.poses, steps, 0.0, settings);
  EXPECT_EQ(all.summary().scans, kScans);
  EXPECT_EQ(all.summary().scans_left_out, 0u);
  EXPECT_TRUE(same_cloud(all.map().cloud(), map_by_hand(0.3, r.poses)));
  settings.trusted_only = true;
  const RunMapBuilder clean = build_run_map(campus(), kFirst, r.poses, steps, 0.0, settings);
  EXPECT_EQ(clean.summary().scans, kScans - 2);
  EXPECT_EQ(clean.summary().scans_left_out, 2u);
  std::vector<bool> leave_out(kScans, false);
  leave_out[3] = leave_out[6] = true;
  EXPECT_TRUE(same_cloud(clean.map().cloud(), map_by_hand(0.3, r.poses, leave_out)));
}

TEST(RunMapBuilder, BadInputIsRefused) {
  RunMapSettings bad;
  bad.voxel = -1.0;
  EXPECT_THROW(RunMapBuilder{bad}, InputError);
  const RunMapBuilder nothing(RunMapSettings{});
  EXPECT_THROW((void)nothing.map(), std::logic_error);
  const std::vector<Eigen::Isometry3d> poses(3, Eigen::Isometry3d::Identity());
  EXPECT_THROW(build_run_map(campus(), 0, poses, std::vector<OdometryStep>(1), 0.0, RunMapSettings{}),
               InputError);
  EXPECT_THROW(build_run_map(campus(), 0, {}, {}, 0.0, RunMapSettings{}), InputError);
}

}  // namespace
}  // namespace sextant
