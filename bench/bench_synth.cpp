// Synthetic campus generation speed. Target (issue 3): the default 468-scan dataset in ≤ 60 s
// on a 2-core machine, in memory; writing the uos folder is measured separately.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "sextant/synth/campus_io.hpp"

namespace {

using sextant::synth::Campus;
using sextant::synth::CampusSettings;

/// One scan of the default sensor (≈ 20,000 points).
void BM_SingleScan(benchmark::State& state) {
  const Campus campus = sextant::synth::generate_campus(CampusSettings{}, 1);
  std::size_t i = 0, points = 0;
  for (auto _ : state) {
    const auto scan = campus.scan(i++ % campus.size());
    points += scan.cloud.size();
    benchmark::DoNotOptimize(scan.cloud.data());
  }
  state.counters["points/s"] = benchmark::Counter(static_cast<double>(points), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SingleScan)->Unit(benchmark::kMillisecond);

/// World, trajectory, odometry, GNSS and all 468 scans in memory (TBB, all cores).
void BM_GenerateDefaultCampusInMemory(benchmark::State& state) {
  for (auto _ : state) {
    const Campus campus = sextant::synth::generate_campus(CampusSettings{}, 1);
    const auto scans = sextant::synth::generate_all_scans(campus);
    benchmark::DoNotOptimize(scans.data());
    state.counters["scans"] = static_cast<double>(scans.size());
  }
}
BENCHMARK(BM_GenerateDefaultCampusInMemory)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

/// Generation plus writing the uos folder (≈ 9 MB of ASCII per 20 scans) to a temporary folder.
void BM_GenerateAndWriteDefaultCampus(benchmark::State& state) {
  const auto folder = std::filesystem::temp_directory_path() / "sextant-bench-synth";
  for (auto _ : state) {
    std::filesystem::remove_all(folder);
    sextant::synth::write_campus(sextant::synth::generate_campus(CampusSettings{}, 1), folder);
  }
  std::filesystem::remove_all(folder);
}
BENCHMARK(BM_GenerateAndWriteDefaultCampus)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
