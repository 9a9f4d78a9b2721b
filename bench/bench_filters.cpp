// Per-step update time of the plane-SLAM filters vs the number of landmarks (50 → 800):
// the EKF's covariance update grows quadratically with the map, the SEIF's measurement and
// motion updates stay flat (bounded active set, block-sparse information matrix); and the cost
// of gating one association (SEIF: Markov-blanket covariance).
//   build-*/bench/bench_filters --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include <memory>

#include "sextant/core/rng.hpp"
#include "sextant/filters/gaussian_filters.hpp"
#include "sextant/filters/innovation_gate.hpp"
#include "sextant/filters/plane_slam_model.hpp"
#include "sextant/filters/seif.hpp"

namespace {

using sextant::Rng;

const Eigen::Matrix4d kR = Eigen::Vector4d(1e-4, 1e-4, 1e-4, 1e-2).asDiagonal();
const Eigen::MatrixXd kQ = Eigen::MatrixXd::Identity(6, 6) * 1e-4;

Eigen::VectorXd control() {
  Eigen::VectorXd u(6);
  u << 0.5, 0.0, 0.0, 0.0, 0.0, 0.01;
  return u;
}

Eigen::VectorXd random_plane(Rng& rng) {
  Eigen::VectorXd m(4);
  const double x = rng.normal(), y = rng.normal(), z = rng.normal();  // in one order on every compiler
  m << Eigen::Vector3d(x, y, z).normalized(), rng.uniform(1.0, 30.0);
  return m;
}

// An EKF over `landmarks` planes with a dense, correlated covariance.
std::unique_ptr<sextant::Ekf> make_ekf(int landmarks) {
  auto model = std::make_shared<sextant::PlaneSlamModel>();
  sextant::GaussianFilterSettings s;
  s.check_covariance = false;  // the O(n³) health check is not part of the update
  auto ekf = std::make_unique<sextant::Ekf>(model, s);
  Rng rng(1);
  const Eigen::Index n = 6 + 4 * static_cast<Eigen::Index>(landmarks);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < landmarks; ++i) x.segment(6 + 4 * i, 4) = random_plane(rng);
  Eigen::MatrixXd P = Eigen::MatrixXd::Constant(n, n, 1e-5);
  P.diagonal().array() += 1e-2;
  ekf->initialize(x, P);
  return ekf;
}

std::unique_ptr<sextant::Seif> make_seif(int landmarks) {
  auto model = std::make_shared<sextant::PlaneSlamModel>();
  sextant::SeifSettings s;
  s.max_active_landmarks = 8;
  auto seif = std::make_unique<sextant::Seif>("seif", model, s);
  seif->initialize(Eigen::VectorXd::Zero(6), Eigen::MatrixXd::Identity(6, 6) * 1e-4);
  Rng rng(1);
  for (int i = 0; i < landmarks; ++i) {
    seif->augment(model->observe(seif->pose(), random_plane(rng)), kR);
    seif->predict(control(), kQ);
  }
  return seif;
}

// Observations of the two most recently added landmarks (active in the SEIF).
void observe_last_two(sextant::Filter& f, std::vector<Eigen::VectorXd>* zs, std::vector<int>* ids) {
  const auto& model = f.model();
  const Eigen::VectorXd x = f.mean();
  for (int id : {f.num_landmarks() - 1, f.num_landmarks() - 2}) {
    ids->push_back(id);
    zs->push_back(model.observe(x.head(6), x.segment(sextant::landmark_offset(model, id), 4)));
  }
}

void BM_EkfUpdate(benchmark::State& state) {
  auto ekf = make_ekf(static_cast<int>(state.range(0)));
  std::vector<Eigen::VectorXd> zs;
  std::vector<int> ids;
  observe_last_two(*ekf, &zs, &ids);
  for (auto _ : state) benchmark::DoNotOptimize(ekf->update(zs, kR, ids));
  state.counters["landmarks"] = static_cast<double>(state.range(0));
}

void BM_EkfPredict(benchmark::State& state) {
  auto ekf = make_ekf(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(ekf->predict(control(), kQ));
  state.counters["landmarks"] = static_cast<double>(state.range(0));
}

void BM_SeifUpdate(benchmark::State& state) {
  auto seif = make_seif(static_cast<int>(state.range(0)));
  std::vector<Eigen::VectorXd> zs;
  std::vector<int> ids;
  observe_last_two(*seif, &zs, &ids);
  for (auto _ : state) benchmark::DoNotOptimize(seif->update(zs, kR, ids));
  state.counters["landmarks"] = static_cast<double>(state.range(0));
  state.counters["touched"] = static_cast<double>(seif->last_step_touched());
}

void BM_SeifPredict(benchmark::State& state) {
  auto seif = make_seif(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(seif->predict(control(), kQ));
  state.counters["landmarks"] = static_cast<double>(state.range(0));
  state.counters["touched"] = static_cast<double>(seif->last_step_touched());
}

// The χ² gate of one association (innovation_gate.hpp): the EKF reads Σ from P, the SEIF inverts
// the information block of the landmark's Markov blanket.
template <class MakeFilter>
void gate_one_association(benchmark::State& state, MakeFilter make) {
  auto filter = make(static_cast<int>(state.range(0)));
  std::vector<Eigen::VectorXd> zs;
  std::vector<int> ids;
  observe_last_two(*filter, &zs, &ids);
  for (auto _ : state) benchmark::DoNotOptimize(sextant::innovation_distance(*filter, zs[0], kR, ids[0]));
  state.counters["landmarks"] = static_cast<double>(state.range(0));
}
void BM_EkfGate(benchmark::State& state) {
  gate_one_association(state, make_ekf);
}
void BM_SeifGate(benchmark::State& state) {
  gate_one_association(state, make_seif);
}

}  // namespace

BENCHMARK(BM_EkfUpdate)->Arg(50)->Arg(100)->Arg(200)->Arg(400)->Arg(800)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EkfPredict)->Arg(50)->Arg(100)->Arg(200)->Arg(400)->Arg(800)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SeifUpdate)->Arg(50)->Arg(100)->Arg(200)->Arg(400)->Arg(800)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SeifPredict)->Arg(50)->Arg(100)->Arg(200)->Arg(400)->Arg(800)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EkfGate)->Arg(50)->Arg(100)->Arg(200)->Arg(400)->Arg(800)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SeifGate)->Arg(50)->Arg(100)->Arg(200)->Arg(400)->Arg(800)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
