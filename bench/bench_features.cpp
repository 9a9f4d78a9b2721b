// Plane-feature kernels: extraction + merging of a ~20,000-point scan (target ≤ 30 ms on one
// core) and semantic association of 50 observed against 1,000 map landmarks (target ≤ 1 ms).
#include <vector>

#include <benchmark/benchmark.h>

#include "../tests/features/synthetic_scene.hpp"
#include "sextant/features/association.hpp"
#include "sextant/features/extraction.hpp"

namespace {

using namespace sextant;

PointCloud twenty_thousand_point_scan() {
  Rng rng(42);
  Eigen::Isometry3d sensor = Eigen::Isometry3d::Identity();
  sensor.translation() = Eigen::Vector3d(1, -2, 1.5);
  // Walls ≈ 10.0k points, ground ≈ 8.8k, blobs 1.5k.
  return test::sample_scene(test::courtyard(), sensor, rng, 14.0, 5.5, 300);
}

void BM_ExtractAndMerge(benchmark::State& state) {
  const PointCloud cloud = twenty_thousand_point_scan();
  PlaneExtractionSettings settings;
  std::size_t landmarks = 0, cell_planes = 0;
  for (auto _ : state) {
    Rng rng(1);
    const PlaneExtraction out = extract_planes(cloud, settings, rng);
    landmarks = out.landmarks.size();
    cell_planes = out.cell_planes.size();
    benchmark::DoNotOptimize(landmarks);
  }
  state.counters["points"] = static_cast<double>(cloud.size());
  state.counters["cell_planes"] = static_cast<double>(cell_planes);
  state.counters["landmarks"] = static_cast<double>(landmarks);
}
BENCHMARK(BM_ExtractAndMerge)->Unit(benchmark::kMillisecond);

// Map landmarks on a 1 km × 1 km campus (random façades), observations near one pose.
std::vector<PlaneLandmark> random_landmarks(std::size_t n, double extent, Rng& rng) {
  std::vector<PlaneLandmark> out;
  for (std::size_t i = 0; i < n; ++i) {
    PlaneLandmark l;
    const double yaw = rng.uniform(0, 2 * M_PI);
    l.plane.normal = Eigen::Vector3d(std::cos(yaw), std::sin(yaw), 0);
    const double x = rng.uniform(-extent, extent), y = rng.uniform(-extent, extent), z = rng.uniform(1, 5);
    l.centroid = Eigen::Vector3d(x, y, z);  // drawn in one order under every compiler
    l.plane.d = l.plane.normal.dot(l.centroid);
    const Eigen::Vector3d along(-std::sin(yaw), std::cos(yaw), 0);
    l.covariance = 8.0 * along * along.transpose() +
                   3.0 * Eigen::Matrix3d(Eigen::Vector3d(0, 0, 1).asDiagonal()) +
                   1e-4 * Eigen::Matrix3d::Identity();
    l.inlier_count = 500;
    out.push_back(l);
  }
  return out;
}

void BM_Associate(benchmark::State& state) {
  Rng rng(7);
  const auto map_size = static_cast<std::size_t>(state.range(0));
  const auto observed_size = static_cast<std::size_t>(state.range(1));
  const std::vector<PlaneLandmark> map = random_landmarks(map_size, 150.0, rng);
  std::vector<PlaneLandmark> observed;
  for (std::size_t i = 0; i < observed_size; ++i) {
    PlaneLandmark l = map[rng.index(map.size())];
    const Eigen::Vector3d along = Eigen::Vector3d::UnitZ().cross(l.plane.normal);
    const double sideways = rng.normal(0, 1.0), up = rng.normal(0, 0.3);
    l.centroid += along * sideways + Eigen::Vector3d::UnitZ() * up;  // in-plane
    observed.push_back(l);
  }
  const AssociationSettings settings;
  std::size_t matches = 0, tested = 0;
  for (auto _ : state) {
    const AssociationResult r = associate_landmarks(observed, map, settings);  // index built inside
    matches = r.matches.size();
    tested = r.candidates_tested;
    benchmark::DoNotOptimize(matches);
  }
  state.counters["matches"] = static_cast<double>(matches);
  state.counters["pairs_tested"] = static_cast<double>(tested);
}
BENCHMARK(BM_Associate)->Args({1000, 50})->Args({10000, 50})->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
