#include "kit/plane_slam_record.hpp"

#include <limits>
#include <optional>
#include <stdexcept>

#include "kit/fbmlndt_motion.hpp"
#include "sextant/filters/eseif.hpp"
#include "sextant/filters/plane_slam.hpp"
#include "sextant/filters/plane_slam_model.hpp"
#include "sextant/filters/seif.hpp"
#include "sextant/filters/slam_runner.hpp"
#include "sextant/synth/odometry.hpp"

namespace sextant {
namespace plane_slam_record {

/// The odometry poses the filters are driven by (campus or resampled), world ← sensor.
std::vector<Eigen::Isometry3d> odometry_poses(const synth::Campus& campus, const PlaneSlamParams& params,
                                              const PlaneSlamMethod& method, std::size_t scans, Rng& rng) {
  if (params.odometry == OdometrySource::kCampus && !method.odometry)
    return {campus.odometry.begin(), campus.odometry.begin() + static_cast<std::ptrdiff_t>(scans)};
  const std::vector<Eigen::Isometry3d> truth(
      campus.ground_truth.begin(), campus.ground_truth.begin() + static_cast<std::ptrdiff_t>(scans));
  return synth::simulate_odometry(truth, method.odometry ? *method.odometry : campus.settings.odometry, rng);
}

/// What every scan records of the filter after it; Ω through Filter::diagnostics().
class Recorder {
 public:
  Recorder(const PlaneSlamParams& params, RecordedRun& run) : params_(params), run_(run) {
    pending_ = params.information_at;
  }

  void record(const Filter& filter, RecordedStep step, std::size_t scan, bool last) {
    step.pose = filter.pose();
    step.map_size = static_cast<std::size_t>(filter.num_landmarks());
    try {
      step.covariance = filter.joint_covariance({});
    } catch (const std::exception&) {
      step.covariance.setConstant(std::numeric_limits<double>::quiet_NaN());
    }
    const FilterDiagnostics diagnostics = filter.diagnostics();
    const BlockInformationMatrix* info = diagnostics.information;
    if (info) step.active = static_cast<double>(info->neighbours(0).size());
    if (params_.marginal_nees) {
      step.has_marginal = true;
      step.marginal = step.covariance;
      if (info && diagnostics.approximate_covariance) {  // SEIF: the exact marginal (Ω⁻¹)_vv
        const Eigen::MatrixXd M = information_marginal(*info, {0});
        if (M.size() == 36)
          step.marginal = M;
        else
          step.marginal.setConstant(std::numeric_limits<double>::quiet_NaN());
      }
    }
    for (auto it = pending_.begin(); info && it != pending_.end();) {
      const bool due = *it == 0 ? last : step.map_size >= *it;
      if (!due) {
        ++it;
        continue;
      }
      run_.information.push_back(pattern(*info, scan, step.map_size));
      it = pending_.erase(it);
    }
    run_.steps.push_back(step);
  }

 private:
  static InformationPattern pattern(const BlockInformationMatrix& omega, std::size_t scan, std::size_t map) {
    InformationPattern p{scan, map, {}};
    for (int i = 0; i < omega.variables(); ++i)
      for (int j : omega.neighbours(i))
        if (j > i) {
          p.links.push_back(i);
          p.links.push_back(j);
        }
    return p;
  }

  const PlaneSlamParams& params_;
  RecordedRun& run_;
  std::vector<std::size_t> pending_;
};

void final_map(const Filter& filter, RecordedRun& run) {
  const Eigen::VectorXd x = filter.mean();
  const PlaneSlamModel model;
  for (int i = 0; i < filter.num_landmarks(); ++i)
    run.map.emplace_back(x.segment<4>(landmark_offset(model, i)));
}

// True planes, true association: the observation model (4.64) from the true pose plus N(0, R),
// driven by run_slam; scan 0 observes at the initial pose without a motion update (empty u).
void run_true(const CampusScans& data, const PlaneSlamParams& params, const PlaneSlamSettings& s,
              const std::vector<Vector6d>& u, std::size_t scans, Rng& noise, RecordedRun& run) {
  const synth::Campus& c = *data.campus;
  const auto model = std::make_shared<PlaneSlamModel>();
  std::vector<SlamStepInput> steps(scans);
  for (std::size_t k = 0; k < scans; ++k) {
    if (k > 0) steps[k].u = u[k];
    const Vector6d truth = to_pose6(c.ground_truth[k]).vector();
    for (const synth::LandmarkVisibility& v : data.visible[k]) {
      if (v.points < params.min_points) continue;
      const synth::Landmark& l = c.world->landmarks[static_cast<std::size_t>(v.landmark)];
      const Eigen::Vector4d m(l.normal.x(), l.normal.y(), l.normal.z(), l.d);
      Eigen::VectorXd z = model->observe(truth, m);
      // Drawn last argument first: the order GCC gave these once-unsequenced draws (same data as before).
      const double nz = noise.normal(), ny = noise.normal(), nx = noise.normal();
      z.head<3>() += s.sigma_normal * Eigen::Vector3d(nx, ny, nz);
      z.head<3>().normalize();
      z[3] += s.sigma_distance * noise.normal();
      steps[k].observations.push_back({z, l.id});
    }
  }
  auto filter = s.build_filter(model);
  filter->initialize(to_pose6(c.ground_truth[0]).vector(), s.initial_covariance());
  Recorder recorder(params, run);
  SlamRunSettings settings;
  settings.record_pose_covariance = false;  // the recorder reads joint_covariance
  const SlamRunResult result = run_slam(*filter, steps, s.process_noise(), s.observation_noise(), settings,
                                        {}, [&](std::size_t k, const SlamStepRecord& r, const Filter& f) {
                                          RecordedStep step;
                                          step.motion_seconds = r.predict_seconds;
                                          step.measurement_seconds = r.update_seconds + r.augment_seconds;
                                          step.ok = r.ok();
                                          step.updated = r.update_status == StepStatus::kOk ? r.updated : 0;
                                          step.augmented = r.augmented;
                                          recorder.record(f, step, k, k + 1 == scans);
                                        });
  run.map_truth.assign(static_cast<std::size_t>(filter->num_landmarks()), -1);
  for (const auto& [id, index] : result.landmark_index)
    run.map_truth.at(static_cast<std::size_t>(index)) = id;
  run.summary = filter->summary();
  const FilterDiagnostics diagnostics = filter->diagnostics();
  run.relocations = diagnostics.relocations;
  run.skipped_relocations = diagnostics.skipped_relocations;
  final_map(*filter, run);
}

// Extraction, semantic association and the χ² gate, driven by run_plane_slam; the prediction from
// the odometry or, motion: fbmlndt, from FbML-NDT on the same extraction (kit/fbmlndt_motion.hpp).
void run_extracted(const CampusScans& data, const PlaneSlamParams& params, const PlaneSlamSettings& s,
                   const std::vector<Eigen::Isometry3d>& odometry, std::size_t scans, std::uint64_t seed,
                   const PlaneSlamMethod& method, RecordedRun& run) {
  const synth::Campus& c = *data.campus;
  std::optional<FbmlndtMotion> hybrid;
  if (method.motion == MotionSource::kFbmlndt)
    hybrid.emplace(method.matcher, params.hybrid, "<" + method.name + ">");
  HybridMotion last;  // the hybrid motion of the scan being stepped
  PlaneSlamMotionSource motion;
  if (hybrid)
    motion = [&](std::size_t k, const PlaneExtraction& extraction, const Filter& filter,
                 const MotionIncrement& odometry_motion) {
      last = hybrid->motion(data.clouds.at(k - 1), data.clouds.at(k), extraction, filter.pose(),
                            odometry_motion);
      return last.motion;
    };
  Recorder recorder(params, run);
  const PlaneSlamRun result = run_plane_slam(
      s, scans, [&](std::size_t k) { return data.clouds.at(k); }, odometry, to_pose6(c.ground_truth[0]), seed,
      [&](std::size_t k, const PlaneSlamStep& r, const Filter& filter) {
        RecordedStep step;
        step.motion_seconds = r.filter.predict_seconds;
        step.measurement_seconds = r.filter.update_seconds + r.filter.augment_seconds;
        step.extraction_seconds = r.extraction_seconds;
        step.association_seconds = r.association_seconds;
        if (hybrid && k > 0) {
          step.registration_seconds = last.seconds;
          step.matched_motion = last.matched ? 1 : 0;
        }
        step.updated = r.filter.updated;
        step.augmented = r.filter.augmented;
        step.gated = r.gated;
        step.ok = r.filter.ok();
        recorder.record(filter, step, k, k + 1 == scans);
        if (k + 1 == scans) final_map(filter, run);
      },
      motion);
  run.summary = result.summary;
  run.map_truth.assign(run.map.size(), -1);
}

}  // namespace plane_slam_record

RecordedRun record_plane_slam(const CampusScans& data, const PlaneSlamParams& params,
                              const PlaneSlamSettings& settings, std::size_t scans, std::uint64_t seed,
                              const PlaneSlamMethod& method) {
  const synth::Campus& c = *data.campus;
  if (scans < 2 || scans > c.size()) throw std::invalid_argument("record_plane_slam: bad scan count");
  Rng rng(seed);
  Rng odometry_rng = rng.split(), noise = rng.split();
  const std::vector<Eigen::Isometry3d> odometry =
      plane_slam_record::odometry_poses(c, params, method, scans, odometry_rng);
  // Increments u_k = o(k−1) ⊖ o(k) (eq. 4.72) and the dead reckoning they give from the true start.
  const PlaneSlamModel model;
  RecordedRun run;
  std::vector<Vector6d> u(scans, Vector6d::Zero());
  run.odometry.push_back(to_pose6(c.ground_truth[0]));
  for (std::size_t k = 1; k < scans; ++k) {
    u[k] = odometry_increment(to_pose6(odometry[k - 1]), to_pose6(odometry[k]));
    run.odometry.push_back(Pose6::from_vector(model.process(run.odometry.back().vector(), u[k])));
  }
  if (landmark_source(params, method) == LandmarkSource::kTrue)
    plane_slam_record::run_true(data, params, settings, u, scans, noise, run);
  else
    plane_slam_record::run_extracted(data, params, settings, odometry, scans, seed, method, run);
  return run;
}

}  // namespace sextant
