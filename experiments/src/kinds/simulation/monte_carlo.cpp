// E15 (§5.2.1.3 A, eqs. 5.7–5.9, figs 5.35–5.36): range–bearing point-landmark SLAM, a paired
// Monte Carlo of any filters of the catalogue (UKF vs RSPKF). One world for every run (drawn from
// the config seed); one run = one (filter, repetition); every filter of a repetition sees the
// same noisy controls and observations (Rng(run.seed)), so differences are paired.
//
//   params:
//     model: range_bearing
//     landmarks: 20            # point landmarks near the edges of a square loop
//     side: 50                 # loop side [m]
//     sim: {RangeBearingSimSettings keys}   # speed, dt, observe_every, sigma_speed, ...
//     initial_sigma: [0.001, 0.001, 0.001]  # P0 = diag(σ²) of the pose (the start is known)
//     record_every: 50         # steps between recorded errors [count]
//     bias_band: {position: 0.5, heading_deg: 0.5}   # "no bias": the mean signed error's interval within
//     ±band baseline: ukf            # method names compared in the claims proposed: rspkf
//   methods: [{name: ukf, filter: ukf, settings: {}}, {name: rspkf, filter: rspkf, settings: {iterations:
//   3}}]
//
// The filters use Q = diag(σ_V², σ_γ²) and R = diag(σ_r², σ_b²) of the simulated noise (the
// thesis writes Q = R = diag(1, π/180): the σ's of 1 m/s, 1°, 1 m and 1°).
#include <cmath>
#include <stdexcept>
#include <string>

#include "kit/number_format.hpp"
#include "kit/row_keys.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/core/units.hpp"
#include "sextant/filters/filter.hpp"
#include "sextant/filters/range_bearing_sim.hpp"
#include "sextant/filters/slam_run_failure.hpp"
#include "sextant/filters/yaml.hpp"
#include "simulation/layouts/layouts.hpp"
#include "simulation/monte_carlo_report.hpp"
#include "simulation/row_keys.hpp"

namespace sextant {
namespace {

RangeBearingSimSettings read_sim(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  RangeBearingSimSettings s;
  in.read("speed", s.speed);
  in.read("dt", s.dt);
  in.read("wheelbase", s.wheelbase);
  in.read("max_steer", s.max_steer);
  in.read("max_steer_rate", s.max_steer_rate);
  in.read("observe_every", s.observe_every);
  in.read("max_range", s.max_range);
  in.read("sigma_speed", s.sigma_speed);
  in.read("sigma_steer", s.sigma_steer);
  in.read("sigma_range", s.sigma_range);
  in.read("sigma_bearing", s.sigma_bearing);
  in.read("waypoint_radius", s.waypoint_radius);
  in.read("max_steps", s.max_steps);
  in.finish();
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
  return s;
}

}  // namespace

MonteCarloParams read_monte_carlo_params(const ExperimentConfig& config) {
  SettingsReader in(config.params, config.file);
  std::string model;
  in.read("model", model);
  MonteCarloParams p;
  in.read("landmarks", p.landmarks);
  in.read("side", p.side);
  p.sim = read_sim(in.child("sim"), config.file);
  std::vector<double> sigma;
  if (in.read("initial_sigma", sigma)) {
    if (sigma.size() != 3 || sigma[0] < 0 || sigma[1] < 0 || sigma[2] < 0)
      in.fail("initial_sigma", "key 'initial_sigma': three σ ≥ 0 (x, y, heading)");
    p.initial_sigma = Eigen::Vector3d(sigma[0], sigma[1], sigma[2]);
  }
  in.read("record_every", p.record_every);
  const YAML::Node band = in.child("bias_band");
  SettingsReader b(band, config.file);
  b.read("position", p.bias_band_position);
  b.read("heading_deg", p.bias_band_heading_deg);
  b.finish();
  in.read("baseline", p.baseline);
  in.read("proposed", p.proposed);
  in.finish();
  if (p.landmarks < 1) in.fail("landmarks", "key 'landmarks' must be >= 1");
  if (!(p.side > 0)) in.fail("side", "key 'side' must be > 0");
  if (p.record_every < 1) in.fail("record_every", "key 'record_every' must be >= 1");
  if (!(p.bias_band_position > 0) || !(p.bias_band_heading_deg > 0))
    in.fail("bias_band", "key 'bias_band': position and heading_deg must be > 0");
  bool baseline = false, proposed = false;
  for (const auto& m : config.methods) baseline |= m.name == p.baseline, proposed |= m.name == p.proposed;
  if (!baseline) in.fail("baseline", "key 'baseline': no method named '" + p.baseline + "'");
  if (!proposed) in.fail("proposed", "key 'proposed': no method named '" + p.proposed + "'");
  return p;
}

FilterSpec read_range_bearing_filter(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  std::string name, filter;
  in.require("name", name);
  in.require("filter", filter);
  const YAML::Node settings = in.child("settings");
  in.finish();
  return read_filter_spec(filter, settings, file, RangeBearingModel().pose_dim());
}

void validate_range_bearing(const ExperimentConfig& config) {
  (void)read_monte_carlo_params(config);
  for (const auto& m : config.methods) (void)read_range_bearing_filter(m.node, config.file);
  if (!config.sweep.empty())
    throw InputError(config.file, "", "key 'sweep': range_bearing takes no sweep axes");
}

void run_range_bearing(const ExperimentConfig& config, const RunSpec& spec, RunRow& row) {
  const MonteCarloParams p = read_monte_carlo_params(config);
  FilterSpec filter_spec = read_range_bearing_filter(config.methods.at(spec.method_index).node, config.file);
  Rng world_rng(config.seed);
  const RangeBearingWorld world = make_range_bearing_world(p.landmarks, p.side, world_rng);
  Rng rng(spec.seed);
  const RangeBearingRun sim = simulate_range_bearing(world, p.sim, rng);

  // The RSPKF draws its random sigma points from its own seed: a different one per repetition.
  if (RspkfSettings* rspkf = filter_spec.get<RspkfSettings>(); rspkf && !rspkf->seed)
    rspkf->seed = spec.seed % 1000000007ULL;
  auto model = std::make_shared<RangeBearingModel>(p.sim.model());
  auto filter = make_filter(filter_spec, model);
  filter->initialize(Eigen::VectorXd::Zero(3), p.initial_sigma.cwiseAbs2().asDiagonal().toDenseMatrix());
  const SlamRunResult result = run_slam(*filter, sim.steps, p.sim.control_noise(), p.sim.observation_noise());
  const std::string failure =
      slam_run_failure(result.landmark_index.size(), result.failed_steps, result.steps.size());
  if (!failure.empty())
    throw std::runtime_error(failure + " (of " + std::to_string(p.landmarks) + " landmarks)");

  // Dead reckoning of the same noisy controls (eq. 5.7 without noise terms).
  Eigen::VectorXd odo = Eigen::VectorXd::Zero(3);
  std::vector<double> t, pos, head, truth_x, truth_y, est_x, est_y;
  double sum_pos = 0, sum_head = 0, sum_odo = 0, along = 0, cross = 0, signed_head = 0, max_pos = 0;
  const std::size_t n = std::min(result.steps.size(), sim.true_poses.size());
  for (std::size_t k = 0; k < n; ++k) {
    odo = model->process(odo, sim.steps[k].u);
    const Eigen::Vector3d truth = sim.true_poses[k];
    const Eigen::Vector3d est = result.steps[k].pose.head<3>();
    const Eigen::Vector2d e = (est - truth).head<2>();
    const double eh = wrap_angle(est.z() - truth.z());
    const Eigen::Vector2d forward(std::cos(truth.z()), std::sin(truth.z()));
    sum_pos += e.norm(), sum_head += std::abs(eh), sum_odo += (odo.head<2>() - truth.head<2>()).norm();
    along += e.dot(forward), cross += forward.x() * e.y() - forward.y() * e.x(), signed_head += eh;
    max_pos = std::max(max_pos, e.norm());
    if ((k + 1) % static_cast<std::size_t>(p.record_every) != 0 && k + 1 != n) continue;
    t.push_back(static_cast<double>(k + 1) * p.sim.dt);
    pos.push_back(e.norm()), head.push_back(std::abs(eh) / kRadPerDeg);
    truth_x.push_back(truth.x()), truth_y.push_back(truth.y()), est_x.push_back(est.x()),
        est_y.push_back(est.y());
  }
  const double count = static_cast<double>(n);
  row.values["steps"] = count;
  row.values[keys::kFailedSteps] = static_cast<double>(result.failed_steps);
  row.values["landmarks_mapped"] = static_cast<double>(result.landmark_index.size());
  row.values[keys::kMeanPositionErrorM] = sum_pos / count;
  row.values[keys::kMeanHeadingErrorDeg] = sum_head / count / kRadPerDeg;
  row.values["max_position_error_m"] = max_pos;
  row.values[keys::kFinalPositionErrorM] = pos.empty() ? NAN : pos.back();
  row.values[keys::kDeadReckoningErrorM] = sum_odo / count;
  row.values[keys::kMeanAlongTrackM] = along / count;
  row.values[keys::kMeanCrossTrackM] = cross / count;
  row.values[keys::kMeanSignedHeadingDeg] = signed_head / count / kRadPerDeg;
  row.series["t"] = t;
  row.series[keys::kPositionErrorM] = pos;
  row.series[keys::kHeadingErrorDeg] = head;
  if (spec.repetition == 0) {  // fig. 5.36: one run's paths and map
    row.series[keys::kTruthX] = truth_x, row.series[keys::kTruthY] = truth_y;
    row.series[keys::kEstX] = est_x, row.series[keys::kEstY] = est_y;
    const Eigen::VectorXd mean = filter->mean();
    std::vector<double> mx, my;
    for (const auto& [id, index] : result.landmark_index) {
      mx.push_back(mean[3 + 2 * index]);
      my.push_back(mean[4 + 2 * index]);
    }
    row.series[keys::kMapX] = mx, row.series[keys::kMapY] = my;
  }
}

ReportSection range_bearing_report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                                   const std::vector<const RunRow*>& rows) {
  const MonteCarloParams p = read_monte_carlo_params(config);
  Rng world_rng(config.seed);
  return monte_carlo_report(config, p, make_range_bearing_world(p.landmarks, p.side, world_rng), runs, rows);
}

}  // namespace sextant
