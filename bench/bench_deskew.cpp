// What deskewing a scan costs (odometry/deskew.hpp): the KITTI scan (124,668 points) given the times of
// a spinning lidar's sweep, one time per firing (a column of 64 rings, 1,948 firings: one pose per
// firing), and of a solid-state lidar (every point its own time: one pose per point), deskewed by a
// car's motion at 10 m/s turning 20°/s over 0.1 s. Run:
//   build/bench/bench_deskew --benchmark_repetitions=7 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/se3.hpp"
#include "sextant/odometry/deskew.hpp"

namespace sextant {
namespace {

constexpr double kSweep = 0.1;  // [s]

PointCloud timed_scan(bool per_firing) {
  PointCloud scan = read_cloud(std::string(SEXTANT_DATA_DIR) + "/kitti00_pair/000000.xyz32.bin");
  std::vector<float> time(scan.size());
  for (std::size_t i = 0; i < scan.size(); ++i) {
    const std::size_t slot = per_firing ? i / 64 : i;  // rings of one firing share its time
    const std::size_t slots = per_firing ? (scan.size() + 63) / 64 : scan.size();
    time[i] = static_cast<float>(kSweep * static_cast<double>(slot) / static_cast<double>(slots));
  }
  scan.set_time(std::move(time));
  return scan;
}

SweepMotion car_motion() {
  Vector6d twist;
  twist << 1.0, 0.0, 0.0, 0.0, 0.0, 20.0 * M_PI / 180.0 * kSweep;  // 10 m/s, 20°/s over the sweep
  return {se3_exp(twist), kSweep};
}

void BM_DeskewSpinningLidar(benchmark::State& state) {
  const PointCloud scan = timed_scan(true);
  const SweepMotion sweep = car_motion();
  for (auto _ : state) benchmark::DoNotOptimize(deskew_scan(scan, sweep));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(scan.size()));
}
BENCHMARK(BM_DeskewSpinningLidar)->Unit(benchmark::kMillisecond);

void BM_DeskewEveryPointItsTime(benchmark::State& state) {
  const PointCloud scan = timed_scan(false);
  const SweepMotion sweep = car_motion();
  for (auto _ : state) benchmark::DoNotOptimize(deskew_scan(scan, sweep));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(scan.size()));
}
BENCHMARK(BM_DeskewEveryPointItsTime)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sextant

BENCHMARK_MAIN();
