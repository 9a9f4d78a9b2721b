#include "kit/plane_slam_driver.hpp"

#include <limits>
#include <map>
#include <optional>
#include <stdexcept>

#include "kit/fbmlndt_motion.hpp"
#include "sextant/filters/eseif.hpp"
#include "sextant/filters/plane_slam.hpp"
#include "sextant/filters/plane_slam_model.hpp"
#include "sextant/filters/seif.hpp"
#include "sextant/synth/odometry.hpp"

namespace sextant {
namespace {

/// The odometry poses the filters are driven by (campus or resampled), world ← sensor.
std::vector<Eigen::Isometry3d> odometry_poses(const synth::Campus& campus, const PlaneSlamParams& params,
                                              const PlaneSlamMethod& method, std::size_t scans, Rng& rng) {
  if (params.odometry == OdometrySource::kCampus && !method.odometry)
    return {campus.odometry.begin(), campus.odometry.begin() + static_cast<std::ptrdiff_t>(scans)};
  const std::vector<Eigen::Isometry3d> truth(
      campus.ground_truth.begin(), campus.ground_truth.begin() + static_cast<std::ptrdiff_t>(scans));
  return synth::simulate_odometry(truth, method.odometry ? *method.odometry : campus.settings.odometry, rng);
}

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
    const auto* seif = dynamic_cast<const Seif*>(&filter);
    const auto* eseif = dynamic_cast<const Eseif*>(&filter);
    const BlockInformationMatrix* info = seif    ? &seif->information()
                                         : eseif ? &eseif->information()
                                                 : nullptr;
    if (info) step.active = static_cast<double>(info->neighbours(0).size());
    if (params_.marginal_nees) {
      step.has_marginal = true;
      step.marginal = step.covariance;
      if (seif) {
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

// True planes, true association: the observation model (4.64) from the true pose plus N(0, R).
void run_true(const CampusScans& data, const PlaneSlamParams& params, const PlaneSlamSettings& s,
              const std::vector<Vector6d>& u, std::size_t scans, Rng& noise, RecordedRun& run) {
  const synth::Campus& c = *data.campus;
  const auto model = std::make_shared<PlaneSlamModel>();
  auto filter = s.build_filter(model);
  filter->initialize(to_pose6(c.ground_truth[0]).vector(), s.initial_covariance());
  const Matrix6d Q = s.process_noise();
  const Eigen::Matrix4d R = s.observation_noise();
  std::map<int, int> index;  // true id → filter landmark
  Recorder recorder(params, run);
  for (std::size_t k = 0; k < scans; ++k) {
    RecordedStep step;
    if (k > 0) {
      const StepResult r = filter->predict(u[k], Q);
      step.motion_seconds = r.seconds;
      step.ok = r.ok();
    }
    const Vector6d truth = to_pose6(c.ground_truth[k]).vector();
    std::vector<Eigen::VectorXd> zs, fresh;
    std::vector<int> associations, fresh_ids;
    for (const synth::LandmarkVisibility& v : data.visible[k]) {
      if (v.points < params.min_points) continue;
      const synth::Landmark& l = c.world->landmarks[static_cast<std::size_t>(v.landmark)];
      const Eigen::Vector4d m(l.normal.x(), l.normal.y(), l.normal.z(), l.d);
      Eigen::VectorXd z = model->observe(truth, m);
      z.head<3>() += s.sigma_normal * Eigen::Vector3d(noise.normal(), noise.normal(), noise.normal());
      z.head<3>().normalize();
      z[3] += s.sigma_distance * noise.normal();
      const auto it = index.find(l.id);
      if (it == index.end()) {
        fresh.push_back(z);
        fresh_ids.push_back(l.id);
      } else {
        zs.push_back(z);
        associations.push_back(it->second);
      }
    }
    if (!zs.empty()) {
      const StepResult r = filter->update(zs, R, associations);
      step.measurement_seconds += r.seconds;
      step.ok = step.ok && r.ok();
      if (r.ok()) step.updated = zs.size();
    }
    for (std::size_t i = 0; i < fresh.size(); ++i) {
      const int before = filter->num_landmarks();
      const StepResult r = filter->augment(fresh[i], R);
      step.measurement_seconds += r.seconds;
      step.ok = step.ok && r.ok();
      if (filter->num_landmarks() == before + 1) {
        index[fresh_ids[i]] = before;
        run.map_truth.push_back(fresh_ids[i]);
        ++step.augmented;
      }
    }
    recorder.record(*filter, step, k, k + 1 == scans);
  }
  run.summary = filter->summary();
  if (const auto* eseif = dynamic_cast<const Eseif*>(filter.get())) {
    run.relocations = eseif->relocations();
    run.skipped_relocations = eseif->skipped_relocations();
  }
  final_map(*filter, run);
}

// Extraction, semantic association and the χ² gate (filters/plane_slam.hpp); the prediction from
// the odometry or, motion: fbmlndt, from FbML-NDT on the same extraction (kit/fbmlndt_motion.hpp).
void run_extracted(const CampusScans& data, const PlaneSlamParams& params, const PlaneSlamSettings& s,
                   const std::vector<Vector6d>& u, std::size_t scans, std::uint64_t seed,
                   const PlaneSlamMethod& method, RecordedRun& run) {
  const synth::Campus& c = *data.campus;
  PlaneSlam slam(s, to_pose6(c.ground_truth[0]), seed);
  std::optional<FbmlndtMotion> hybrid;
  if (method.motion == MotionSource::kFbmlndt)
    hybrid.emplace(method.matcher, params.hybrid, "<" + method.name + ">");
  Recorder recorder(params, run);
  for (std::size_t k = 0; k < scans; ++k) {
    const PlaneExtraction& extraction = slam.extract(data.clouds.at(k));
    HybridMotion motion;
    motion.motion = {u[k], s.process_noise()};
    if (hybrid && k > 0)
      motion = hybrid->motion(data.clouds.at(k - 1), data.clouds.at(k), extraction, slam.filter().pose(),
                              motion.motion);
    const PlaneSlamStep r = slam.step(motion.motion.u, motion.motion.Q);
    RecordedStep step;
    step.motion_seconds = r.filter.predict_seconds;
    step.measurement_seconds = r.filter.update_seconds + r.filter.augment_seconds;
    step.extraction_seconds = r.extraction_seconds;
    step.association_seconds = r.association_seconds;
    step.registration_seconds = motion.seconds;
    if (hybrid && k > 0) step.matched_motion = motion.matched ? 1 : 0;
    step.updated = r.filter.updated;
    step.augmented = r.filter.augmented;
    step.gated = r.gated;
    step.ok = r.filter.ok();
    recorder.record(slam.filter(), step, k, k + 1 == scans);
  }
  run.summary = slam.filter().summary();
  final_map(slam.filter(), run);
  run.map_truth.assign(run.map.size(), -1);
}

}  // namespace

RecordedRun record_plane_slam(const CampusScans& data, const PlaneSlamParams& params,
                              const PlaneSlamSettings& settings, std::size_t scans, std::uint64_t seed,
                              const PlaneSlamMethod& method) {
  const synth::Campus& c = *data.campus;
  if (scans < 2 || scans > c.size()) throw std::invalid_argument("record_plane_slam: bad scan count");
  Rng rng(seed);
  Rng odometry_rng = rng.split(), noise = rng.split();
  const std::vector<Eigen::Isometry3d> odometry = odometry_poses(c, params, method, scans, odometry_rng);
  // Increments u_k = o(k−1) ⊖ o(k) (eq. 4.72) and the dead reckoning they give from the true start.
  const PlaneSlamModel model;
  RecordedRun run;
  std::vector<Vector6d> u(scans, Vector6d::Zero());
  run.odometry.push_back(to_pose6(c.ground_truth[0]));
  for (std::size_t k = 1; k < scans; ++k) {
    u[k] = odometry_increment(to_pose6(odometry[k - 1]), to_pose6(odometry[k]));
    run.odometry.push_back(Pose6::from_vector(model.process(run.odometry.back().vector(), u[k])));
  }
  if (params.landmarks == LandmarkSource::kTrue)
    run_true(data, params, settings, u, scans, noise, run);
  else
    run_extracted(data, params, settings, u, scans, seed, method, run);
  return run;
}

}  // namespace sextant
