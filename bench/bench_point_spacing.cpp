// measure_point_spacing (sextant/matchers/point_spacing.hpp) on real scans: the k-d tree over the whole
// scan and at most 2,000 nearest-neighbour queries, what the opt-in `precision_spacing_cells` pays per
// reference (docs/matcher_defaults.md, "Precision cells from the point spacing"). Run:
//   build/bench/bench_point_spacing --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// Argument 0 is a KITTI scan (124,668 points), 1 a Velodyne pair scan (69,088), 2 every 5th point of it.
#include <benchmark/benchmark.h>

#include <array>
#include <string>
#include <vector>

#include "sextant/core/io/cloud_io.hpp"
#include "sextant/matchers/point_spacing.hpp"

namespace sextant {
namespace {

const PointCloud& scan(int which) {
  static const std::array<PointCloud, 3> scans = [] {
    const std::string d = SEXTANT_DATA_DIR;
    std::array<PointCloud, 3> s;
    s[0] = read_cloud(d + "/kitti00_pair/000000.xyz32.bin");
    s[1] = read_cloud(d + "/velodyne_pair/fast_gicp_251370668.pcd");
    std::vector<std::size_t> fifth;
    for (std::size_t i = 0; i < s[1].size(); i += 5) fifth.push_back(i);
    s[2] = s[1].subset(fifth);
    return s;
  }();
  return scans[static_cast<std::size_t>(which)];
}

void BM_PointSpacing(benchmark::State& state) {
  const PointCloud& cloud = scan(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(measure_point_spacing(cloud).median);
  state.counters["points"] = static_cast<double>(cloud.size());
  state.counters["spacing_m"] = measure_point_spacing(cloud).median;
}
BENCHMARK(BM_PointSpacing)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sextant

BENCHMARK_MAIN();
