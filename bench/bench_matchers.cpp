// Matcher kernels (issue 4, "Performance"): one Mahalanobis score + gradient + Hessian
// evaluation over 20,000 points on a layer with 10⁴–10⁵ cells (target ≤ 30 ns per point on one
// core), the same for the Gaussian (P2D-NDT) score, the layer-pyramid build per 100k reference
// points, ML-NDT's whole reference model (pyramid and precision grids), the GBS sampler, and one
// whole ML-NDT registration; the Mahalanobis evaluation also
// over 1 and 2 TBB threads (BM_MahalanobisKernelThreads, wall-clock ns per point). Issue 14's
// targets, one thread: kernel (BM_MahalanobisKernel/2) ≤ 15 ns per point, the 6-layer pyramid
// (BM_LayerPyramidBuild/100000/6) ≤ 20 ns per reference point. On the shared machine take medians:
//   build-*/bench/bench_matchers --benchmark_counters_tabular=true --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "mlndt/mlndt_global_init.hpp"
#include "ndt/mahalanobis_kernel.hpp"
#include "ndt/ndt_score.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/samplers.hpp"

namespace sextant {
namespace {

/// A deterministic outdoor-like scene of about `n` points over a 120 × 120 m area: sloped
/// ground and box buildings with noisy walls.
PointCloud scene(std::size_t n, std::uint64_t seed) {
  Rng layout(42);  // the same buildings for every seed; `seed` only draws the points
  Rng rng(seed);
  PointCloud cloud;
  cloud.reserve(n);
  struct Box {
    float x0, y0, x1, y1, h;
  };
  std::vector<Box> boxes;
  for (int i = 0; i < 40; ++i) {
    const auto x = static_cast<float>(layout.uniform(-55, 45)),
               y = static_cast<float>(layout.uniform(-55, 45));
    boxes.push_back({x, y, x + static_cast<float>(layout.uniform(3, 12)),
                     y + static_cast<float>(layout.uniform(3, 12)),
                     static_cast<float>(layout.uniform(2, 15))});
  }
  while (cloud.size() < n) {
    if (rng.uniform() < 0.4) {
      const auto x = static_cast<float>(rng.uniform(-60, 60)), y = static_cast<float>(rng.uniform(-60, 60));
      cloud.push_back({x, y, 0.02f * x + 0.03f * static_cast<float>(rng.normal())});
      continue;
    }
    const Box& b = boxes[rng.index(boxes.size())];
    const auto s = static_cast<float>(rng.uniform()), z = static_cast<float>(rng.uniform(0, b.h));
    const auto noise = 0.02f * static_cast<float>(rng.normal());
    switch (rng.index(4)) {
      case 0: cloud.push_back({b.x0 + s * (b.x1 - b.x0), b.y0 + noise, z}); break;
      case 1: cloud.push_back({b.x0 + s * (b.x1 - b.x0), b.y1 + noise, z}); break;
      case 2: cloud.push_back({b.x0 + noise, b.y0 + s * (b.y1 - b.y0), z}); break;
      default: cloud.push_back({b.x1 + noise, b.y0 + s * (b.y1 - b.y0), z}); break;
    }
  }
  return cloud;
}

struct KernelFixture {
  NdtGrid grid;
  PointCloud input;
  Vector6d xi;
  KernelFixture() {
    const PointCloud reference = scene(100000, 1);
    // Layer 5 of q = 8 over this box: about 3·10⁴ cells (the 10⁴–10⁵).
    const LayerGeometry g = layer_geometry(reference.bounds(), 8, 5);
    grid = NdtGrid::build(reference, reference.bounds().min.cast<double>(), g.cell_edge, g.dims);
    const PointCloud scan = scene(20000, 2);
    input = scan;
    xi << 0.3, -0.2, 0.05, 0.01, -0.01, 0.05;
  }
};

const KernelFixture& kernel_fixture() {
  static const KernelFixture f;
  return f;
}

void report_per_point(benchmark::State& state, std::size_t points) {
  state.counters["ns_per_point"] =
      benchmark::Counter(static_cast<double>(points * state.iterations()) * 1e-9,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_MahalanobisKernel(benchmark::State& state) {
  const KernelFixture& f = kernel_fixture();
  const auto mode = static_cast<Derivatives>(state.range(0));
  std::size_t matched = 0;
  for (auto _ : state) {
    const ScoreEvaluation e = mahalanobis_score(f.grid, f.input, f.xi, mode);
    benchmark::DoNotOptimize(e.hessian(5, 5));
    matched = e.matched;
  }
  report_per_point(state, f.input.size());
  state.counters["cells"] = static_cast<double>(f.grid.cell_count());
  state.counters["matched"] = static_cast<double>(matched);
}
BENCHMARK(BM_MahalanobisKernel)
    ->Arg(static_cast<int>(Derivatives::kScore))
    ->Arg(static_cast<int>(Derivatives::kHessian))
    ->Unit(benchmark::kMicrosecond);

// The kernel alone (one block over the whole input, white-box) on each instruction set it is built
// for: Args derivatives, instruction set (0 plain x86-64, 1 AVX2; the same bits, see
// KernelInstructionSet.*). A set the CPU lacks is skipped.
void BM_MahalanobisBlock(benchmark::State& state) {
  const KernelFixture& f = kernel_fixture();
  const auto mode = static_cast<Derivatives>(state.range(0));
  const auto isa = static_cast<InstructionSet>(state.range(1));
  if (!instruction_set_available(isa)) {
    state.SkipWithError("the CPU lacks this instruction set");
    return;
  }
  const Eigen::Isometry3d T = to_isometry(Pose6::from_vector(f.xi));
  const Eigen::Matrix3d R = T.linear();
  const Eigen::Vector3d t = T.translation();
  const Eigen::Vector3f* begin = f.input.points().data();
  for (auto _ : state) {
    score_detail::Sums s;
    score_detail::mahalanobis_block(f.grid, begin, begin + f.input.size(), R, t,
                                    std::numeric_limits<double>::infinity(), mode, s, isa);
    benchmark::DoNotOptimize(s.S(2, 2));
  }
  report_per_point(state, f.input.size());
}
BENCHMARK(BM_MahalanobisBlock)
    ->Args({static_cast<int>(Derivatives::kScore), 0})
    ->Args({static_cast<int>(Derivatives::kScore), 1})
    ->Args({static_cast<int>(Derivatives::kHessian), 0})
    ->Args({static_cast<int>(Derivatives::kHessian), 1})
    ->Unit(benchmark::kMicrosecond);

// The same score + gradient + Hessian evaluation with the blocked accumulation on Arg threads
// (bit-identical results for every count), one ScoreThreads (TBB arena) for all iterations as
// in a registration. Wall-clock time: the calling thread's CPU time would hide the workers.
void BM_MahalanobisKernelThreads(benchmark::State& state) {
  const KernelFixture& f = kernel_fixture();
  const ScoreThreads threads(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const ScoreEvaluation e = mahalanobis_score(f.grid, f.input, f.xi, Derivatives::kHessian,
                                                std::numeric_limits<double>::infinity(), threads);
    benchmark::DoNotOptimize(e.hessian(5, 5));
  }
  report_per_point(state, f.input.size());
  state.counters["threads"] = threads.concurrency();
}
BENCHMARK(BM_MahalanobisKernelThreads)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMicrosecond);

void BM_GaussianKernel(benchmark::State& state) {
  const KernelFixture& f = kernel_fixture();
  const GaussianScoreParams p = GaussianScoreParams::from_outlier_ratio(0.55, f.grid.cell_edge());
  const bool trilinear = state.range(0) != 0;
  for (auto _ : state) {
    const ScoreEvaluation e = gaussian_score(f.grid, f.input, f.xi, p, trilinear, Derivatives::kHessian);
    benchmark::DoNotOptimize(e.hessian(5, 5));
  }
  report_per_point(state, f.input.size());
}
BENCHMARK(BM_GaussianKernel)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// Args: reference points, layers n (q = 8): ns_per_point is per reference point.
void BM_LayerPyramidBuild(benchmark::State& state) {
  const PointCloud reference = scene(static_cast<std::size_t>(state.range(0)), 3);
  LayerPyramidSettings settings;
  settings.layers = static_cast<int>(state.range(1));
  std::size_t gaussians = 0;
  for (auto _ : state) {
    const auto layers = build_layer_pyramid(reference, settings);
    benchmark::DoNotOptimize(layers.back().gaussian_count());
    gaussians = 0;
    for (const NdtGrid& layer : layers) gaussians += layer.gaussian_count();
  }
  report_per_point(state, reference.size());
  state.counters["gaussians"] = static_cast<double>(gaussians);
}
BENCHMARK(BM_LayerPyramidBuild)->Args({100000, 4})->Args({100000, 6})->Unit(benchmark::kMillisecond);

// The same build on a real scan (data/kitti00_pair/000000.xyz32.bin, 124,668 points), Args: layers,
// order (0: as the lidar wrote them, ring by ring; 1: shuffled, as the synthetic scene above draws
// its points). A point's cell is read and written in the points' order: in scan order neighbouring
// points share cells and the cache, shuffled every point misses it.
void BM_LayerPyramidBuildRealScan(benchmark::State& state) {
  static const PointCloud scan = read_cloud(std::string(SEXTANT_DATA_DIR) + "/kitti00_pair/000000.xyz32.bin");
  PointCloud reference = scan;
  if (state.range(1) != 0) {
    std::vector<std::size_t> order(scan.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    Rng rng(5);
    for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng.index(i)]);
    reference = scan.subset(order);
  }
  LayerPyramidSettings settings;
  settings.layers = static_cast<int>(state.range(0));
  std::size_t gaussians = 0;
  for (auto _ : state) {
    const auto layers = build_layer_pyramid(reference, settings);
    benchmark::DoNotOptimize(layers.back().gaussian_count());
    gaussians = 0;
    for (const NdtGrid& layer : layers) gaussians += layer.gaussian_count();
  }
  report_per_point(state, reference.size());
  state.counters["gaussians"] = static_cast<double>(gaussians);
}
BENCHMARK(BM_LayerPyramidBuildRealScan)
    ->Args({4, 0})
    ->Args({6, 0})
    ->Args({6, 1})
    ->Unit(benchmark::kMillisecond);

// ML-NDT's whole reference model (MlndtMatcher::set_reference, default settings: the pyramid and
// the precision stage's two grids) per 100k reference points; Arg: threads (wall-clock time).
void BM_MlndtReferenceModel(benchmark::State& state) {
  const PointCloud reference = scene(100000, 3);
  MlndtSettings settings;
  settings.threads = static_cast<int>(state.range(0));
  MlndtMatcher matcher(settings);
  for (auto _ : state) {
    matcher.set_reference(reference);
    benchmark::DoNotOptimize(matcher.precision_layers().size());
  }
  report_per_point(state, reference.size());
  state.counters["precision_grids"] = static_cast<double>(matcher.precision_layers().size());
}
BENCHMARK(BM_MlndtReferenceModel)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);

// The wide basin's hypothesis scoring (wide_basin_starts, default settings: 10,404 hypotheses
// prescreened with 128 points, the best 512 rescored with 512) on the real KITTI pair, the default
// ML-NDT's layers over scan 0. Odometry's recovery runs it once per start.
void BM_WideBasinStarts(benchmark::State& state) {
  const std::string dir = std::string(SEXTANT_DATA_DIR) + "/kitti00_pair/";
  static const PointCloud reference = read_cloud(dir + "000000.xyz32.bin");
  static const PointCloud input = read_cloud(dir + "000001.xyz32.bin");
  MlndtMatcher matcher;
  matcher.set_reference(reference);
  const WideBasinSettings settings;
  for (auto _ : state) {
    const auto starts = wide_basin_starts(matcher.layers(), input, Eigen::Isometry3d::Identity(), settings);
    benchmark::DoNotOptimize(starts.back().translation().x());
  }
  state.counters["hypotheses"] = static_cast<double>(settings.hypotheses());
}
BENCHMARK(BM_WideBasinStarts)->Unit(benchmark::kMillisecond);

void BM_GridSampler(benchmark::State& state) {
  const PointCloud input = scene(static_cast<std::size_t>(state.range(0)), 4);
  const GridSampler sampler;
  std::size_t kept = 0;
  for (auto _ : state) {
    Rng rng(5);
    kept = sampler.select(input, rng).size();
    benchmark::DoNotOptimize(kept);
  }
  report_per_point(state, input.size());
  state.counters["kept"] = static_cast<double>(kept);
}
BENCHMARK(BM_GridSampler)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_MlndtRegistration(benchmark::State& state) {
  const PointCloud reference = scene(100000, 6);
  Rng rng(7);
  const PointCloud scan = scene(100000, 8);
  const PointCloud input = scan.subset(RandomSampler(RandomSamplerSettings{0.2}).select(scan, rng));
  const Eigen::Isometry3d truth = to_isometry(Pose6{1.0, -0.5, 0.0, 0.0, 0.0, 0.05});
  const PointCloud moved = input.transformed(truth.inverse());
  MlndtSettings settings;
  SolverKind solver = static_cast<SolverKind>(state.range(0));
  settings.optimizer.solver = solver;
  MlndtMatcher matcher(settings);
  matcher.set_reference(reference);
  double error = 0.0;
  for (auto _ : state) {
    const RegistrationResult r = matcher.align(moved, Eigen::Isometry3d::Identity());
    error = translation_norm(truth.inverse() * r.T);
    benchmark::DoNotOptimize(error);
  }
  state.counters["input_points"] = static_cast<double>(moved.size());
  state.counters["error_cm"] = 100.0 * error;
}
BENCHMARK(BM_MlndtRegistration)
    ->Arg(static_cast<int>(SolverKind::kNewton))
    ->Arg(static_cast<int>(SolverKind::kLevenbergMarquardt))
    ->Arg(static_cast<int>(SolverKind::kCeres))
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sextant

BENCHMARK_MAIN();
