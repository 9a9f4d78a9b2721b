// The local map of scan-to-map odometry (odometry/local_map.hpp) on real scans: the KITTI pair
// (124,668 + 124,008 points, 0.1 s apart) moved into scan 1's frame, as `sextant odometry` merges it
// once the window holds two scans, then filtered to one centroid per 0.2 m voxel (the default
// local_map_voxel; a map of dense scans passes local_map_max_points at once). PCL's VoxelGrid
// (centroid per voxel as well) on the same merged points is the peer. Run:
//   build/bench/bench_local_map --benchmark_repetitions=7 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <pcl/filters/voxel_grid.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "sextant/core/io/cloud_io.hpp"
#include "sextant/odometry/local_map.hpp"

namespace sextant {
namespace {

constexpr double kVoxel = 0.2;  // OdometrySettings::local_map_voxel's default [m]

struct Window {
  std::vector<PointCloud> scans;
  std::vector<Eigen::Isometry3d> poses;  // scan 1 ← scan j
};

/// The 3 × 4 row-major matrix of a text file (the pair's scan 0 ← scan 1).
Eigen::Isometry3d read_3x4(const std::string& file) {
  std::ifstream in(file);
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) in >> M(r, c);
  if (!in) throw std::runtime_error("cannot read the 3×4 matrix in " + file);
  return Eigen::Isometry3d(M);
}

const Window& kitti_window() {
  static const Window window = [] {
    const std::string d = std::string(SEXTANT_DATA_DIR) + "/kitti00_pair/";
    Window w;
    w.scans = {read_cloud(d + "000000.xyz32.bin"), read_cloud(d + "000001.xyz32.bin")};
    // T_velo0_from_velo1_DERIVED.txt: scan 0 ← scan 1, so scan 1 ← scan 0 is its inverse.
    w.poses = {read_3x4(d + "T_velo0_from_velo1_DERIVED.txt").inverse(), Eigen::Isometry3d::Identity()};
    return w;
  }();
  return window;
}

PointCloud merged() {
  const Window& w = kitti_window();
  return merge_local_map({&w.scans[0], &w.scans[1]}, w.poses, ~std::size_t{0}, kVoxel);  // unfiltered
}

void BM_MergeAndFilter(benchmark::State& state) {
  const Window& w = kitti_window();
  std::size_t points = 0;
  for (auto _ : state) {
    const PointCloud map = merge_local_map({&w.scans[0], &w.scans[1]}, w.poses, 0, kVoxel);
    points = map.size();
    benchmark::DoNotOptimize(map.points().data());
  }
  state.counters["map_points"] = static_cast<double>(points);
}

void BM_VoxelDownsample(benchmark::State& state) {
  const PointCloud map = merged();
  std::size_t points = 0;
  for (auto _ : state) {
    const PointCloud filtered = voxel_downsample(map, kVoxel);
    points = filtered.size();
    benchmark::DoNotOptimize(filtered.points().data());
  }
  state.counters["input_points"] = static_cast<double>(map.size());
  state.counters["voxels"] = static_cast<double>(points);
}

void BM_PclVoxelGrid(benchmark::State& state) {
  const PointCloud map = merged();
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  for (const Eigen::Vector3f& p : map.points()) cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  pcl::VoxelGrid<pcl::PointXYZ> grid;
  grid.setInputCloud(cloud);
  const auto leaf = static_cast<float>(kVoxel);
  grid.setLeafSize(leaf, leaf, leaf);
  std::size_t points = 0;
  for (auto _ : state) {
    pcl::PointCloud<pcl::PointXYZ> filtered;
    grid.filter(filtered);
    points = filtered.size();
    benchmark::DoNotOptimize(filtered.points.data());
  }
  state.counters["voxels"] = static_cast<double>(points);
}

BENCHMARK(BM_MergeAndFilter)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VoxelDownsample)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PclVoxelGrid)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sextant

BENCHMARK_MAIN();
