// The view of an odometry run (pipeline/odometry_view.hpp): its map is the run's, with voxels merged
// when there are too many; the view has one record per step at the scan it registers, with its trust,
// reason, time and steps.csv's error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sextant/core/pose.hpp"
#include "sextant/pipeline/odometry_view.hpp"

namespace sextant {
namespace {

/// Scan i: the points (1.01, 0.03, 0) and (1.01, 0.13, 0) and one 0.1 m from the sensor, at pose
/// (0, 10 i, 0) (away from the voxels' borders);
/// times 50 + i / 10.
class PointsDataset final : public Dataset {
 public:
  explicit PointsDataset(std::size_t n) {
    meta_.name = "points";
    meta_.scan_count = n;
    meta_.has_ground_truth = true;
  }
  const DatasetMetadata& metadata() const override { return meta_; }
  PointCloud scan(std::size_t, ScanLoadReport* report) const override {
    PointCloud c;
    c.push_back(Eigen::Vector3f(1.01f, 0.03f, 0.0f));
    c.push_back(Eigen::Vector3f(1.01f, 0.13f, 0.0f));
    c.push_back(Eigen::Vector3f(0.1f, 0.0f, 0.0f));
    if (report) report->points_read = c.size();
    return c;
  }
  std::optional<Eigen::Isometry3d> odometry(std::size_t) const override { return std::nullopt; }
  std::optional<Eigen::Isometry3d> ground_truth(std::size_t i) const override { return pose_of(i); }
  std::optional<double> stamp(std::size_t i) const override { return 50.0 + 0.1 * static_cast<double>(i); }
  static Eigen::Isometry3d pose_of(std::size_t i) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(0.0, 10.0 * static_cast<double>(i), 0.0);
    return T;
  }

 private:
  DatasetMetadata meta_;
};

std::vector<Eigen::Isometry3d> points_poses(std::size_t n) {
  std::vector<Eigen::Isometry3d> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(PointsDataset::pose_of(i));
  return out;
}

bool has_point(const PointCloud& cloud, const Eigen::Vector3f& p) {
  return std::any_of(cloud.points().begin(), cloud.points().end(),
                     [&p](const Eigen::Vector3f& q) { return (q - p).norm() < 2e-3f; });
}

/// The run's map of `n` of PointsDataset's scans (without the near point, as the chain drops it).
RunMap points_map(std::size_t n, double voxel = 0.05) {
  const PointsDataset dataset(n);
  RunMap map(voxel);
  for (std::size_t i = 0; i < n; ++i) map.add(load_sequence_scan(dataset, i, 0.5), PointsDataset::pose_of(i));
  return map;
}

TEST(RunViewMap, IsTheRunsMapWhenItIsSmallEnough) {
  const RunViewMap map = run_view_map(points_map(4));
  EXPECT_EQ(map.scans_read, 4u);
  EXPECT_EQ(map.voxel, 0.05);
  ASSERT_EQ(map.points.size(), 8u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(has_point(map.points, Eigen::Vector3f(1.01f, 10.0f * static_cast<float>(i) + 0.03f, 0.0f)))
        << i;
    EXPECT_TRUE(has_point(map.points, Eigen::Vector3f(1.01f, 10.0f * static_cast<float>(i) + 0.13f, 0.0f)))
        << i;
  }
}

TEST(RunViewMap, DoublesTheVoxelUntilFewEnoughPoints) {
  // Too many voxels for the cap: the edge doubles until the two points of a scan share one, whose
  // centroid is their mean.
  const RunViewMap merged = run_view_map(points_map(4), 4);
  EXPECT_DOUBLE_EQ(merged.voxel, 0.2);  // 0.05 → 0.1 → 0.2
  ASSERT_EQ(merged.points.size(), 4u);  // 10 m apart, the scans stay apart
  for (int i = 0; i < 4; ++i)
    EXPECT_TRUE(has_point(merged.points, Eigen::Vector3f(1.01f, 10.0f * static_cast<float>(i) + 0.08f, 0.0f)))
        << i;
  EXPECT_EQ(run_view_map(points_map(4), 1).points.size(), 1u) << "0.05 m doubled up to one voxel of 40 m";
}

TEST(OdometryRunView, OneRecordPerStepAtTheScanItRegisters) {
  const PointsDataset dataset(12);
  OdometryResult result;
  result.poses = points_poses(5);  // scans 7 … 11 as the run's first … fifth
  for (std::size_t i = 0; i < 4; ++i) {
    OdometryStep step;
    step.relative = relative(result.poses[i], result.poses[i + 1]);
    step.first_relative = step.relative;
    step.converged = true;
    step.quality.assessed = true;
    step.quality.trust = Trust::kOk;
    step.status = "converged";
    result.steps.push_back(step);
  }
  result.steps[1].quality.trust = Trust::kLowOverlap;
  result.steps[1].quality.reason = "overlap 0.2 below 0.5";
  result.steps[1].recovery = "last_motion";
  result.steps[2].recovery = "wide_basin";
  result.steps[2].first_trust = Trust::kSuspect;
  result.steps[3].relative.translation().x() += 0.3;  // 0.3 m off the truth
  std::vector<Eigen::Isometry3d> truth;
  for (std::size_t i = 0; i < 5; ++i) truth.push_back(*dataset.ground_truth(7 + i));
  const RunViewMap map = run_view_map(points_map(5));
  const RunView view = odometry_run_view(dataset, 7, result, result.poses, truth, map, "t");
  ASSERT_EQ(view.steps.size(), 4u);
  EXPECT_EQ(view.reference.size(), 5u);
  EXPECT_EQ(view.map.size(), map.points.size());
  for (std::size_t i = 0; i < 4; ++i) {
    const RunViewStep& s = view.steps[i];
    EXPECT_EQ(s.number, i);
    EXPECT_EQ(s.pose, i + 1);
    EXPECT_EQ(s.from_scan, 7 + i);
    EXPECT_EQ(s.to_scan, 8 + i);
    EXPECT_DOUBLE_EQ(s.stamp, 50.0 + 0.1 * static_cast<double>(8 + i));
    EXPECT_NEAR(s.error_m, i == 3 ? 0.3 : 0.0, 1e-9) << i;
  }
  EXPECT_EQ(verdict_of(view.steps[0]), StepVerdict::trusted);
  EXPECT_EQ(verdict_of(view.steps[1]), StepVerdict::untrusted);
  EXPECT_EQ(view.steps[1].reason, "overlap 0.2 below 0.5");
  EXPECT_EQ(view.steps[1].trust, "low_overlap");
  EXPECT_EQ(view.steps[1].recovery, "last_motion");
  EXPECT_EQ(verdict_of(view.steps[2]), StepVerdict::recovered);
  EXPECT_EQ(view.steps[2].first_trust, "suspect");
  // Without the truth: no reference, no errors.
  const RunView blind = odometry_run_view(dataset, 7, result, result.poses, std::nullopt, map, "t");
  EXPECT_TRUE(blind.reference.empty());
  EXPECT_TRUE(std::isnan(blind.steps[3].error_m));
}

}  // namespace
}  // namespace sextant
