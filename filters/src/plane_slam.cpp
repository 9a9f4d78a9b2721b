#include "sextant/filters/plane_slam.hpp"

#include <chrono>
#include <stdexcept>

#include "sextant/core/chi_square.hpp"
#include "sextant/core/units.hpp"
#include "sextant/features/merging.hpp"
#include "sextant/filters/fastslam.hpp"
#include "sextant/filters/innovation_gate.hpp"
#include "sextant/filters/plane_slam_model.hpp"

namespace sextant {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// The worse of two statuses (the first non-ok one is kept).
void keep_first_failure(StepStatus& slot, StepStatus status) {
  if (slot == StepStatus::kOk) slot = status;
}

bool length_sigma(double sigma) {
  return sigma > 0 && sigma <= kMaxSettingLength;
}
bool angle_sigma(double sigma) {
  return sigma > 0 && sigma <= kPi;
}

}  // namespace

bool PlaneSlamSettings::valid(std::string* why) const {
  const char* problem = nullptr;
  if (!default_filter(filter))
    problem = "unknown filter (filter_names(): ckf, eif, ekf, eseif, fastslam2, rspkf, seif, ukf)";
  else if (!(length_sigma(sigma_xy) && length_sigma(sigma_z) && angle_sigma(sigma_roll_pitch) &&
             angle_sigma(sigma_yaw)))
    problem =
        "odometry sigmas must be > 0: sigma_xy and sigma_z at most 1000 m, sigma_roll_pitch and "
        "sigma_yaw at most π rad";
  else if (!(sigma_normal > 0 && sigma_normal <= 1 && length_sigma(sigma_distance)))
    problem =
        "observation sigmas must be > 0: sigma_normal at most 1 (a unit normal's component), "
        "sigma_distance at most 1000 m";
  else if (!(length_sigma(initial_sigma_translation) && angle_sigma(initial_sigma_rotation) && p0_scale > 0 &&
             p0_scale <= kMaxP0Scale))
    problem =
        "initial sigmas must be > 0 (translation at most 1000 m, rotation at most π rad) and p0_scale at "
        "most 1e12";
  else if (!(gate_probability >= 0 && gate_probability < 1))
    problem = "gate_probability must lie in [0, 1) (0 turns the gate off)";
  if (problem) {
    if (why) *why = problem;
    return false;
  }
  return extraction.valid(why) && association.valid(why);
}

std::unique_ptr<Filter> PlaneSlamSettings::build_filter(std::shared_ptr<const SlamModel> model) const {
  if (filter_factory) return filter_factory(std::move(model));
  const FilterFactory make = default_filter(filter);
  if (!make) throw std::invalid_argument("plane SLAM settings: unknown filter '" + filter + "'");
  return make(std::move(model));
}

// Q of the odometry increment u of eq. (4.72).
Matrix6d PlaneSlamSettings::process_noise() const {
  Vector6d d;
  d << sigma_xy * sigma_xy, sigma_xy * sigma_xy, sigma_z * sigma_z, sigma_roll_pitch * sigma_roll_pitch,
      sigma_roll_pitch * sigma_roll_pitch, sigma_yaw * sigma_yaw;
  return d.asDiagonal();
}

// R of one plane observation z = (nᴸ, dᴸ), eq. (4.64).
Eigen::Matrix4d PlaneSlamSettings::observation_noise() const {
  const double n = sigma_normal * sigma_normal;
  return Eigen::Vector4d(n, n, n, sigma_distance * sigma_distance).asDiagonal();
}

Matrix6d PlaneSlamSettings::initial_covariance() const {
  const double t = initial_sigma_translation * initial_sigma_translation;
  const double r = initial_sigma_rotation * initial_sigma_rotation;
  Vector6d d;
  d << t, t, t, r, r, r;
  return p0_scale * Matrix6d(d.asDiagonal());
}

PlaneSlam::PlaneSlam(PlaneSlamSettings settings, const Pose6& initial_pose, std::uint64_t seed)
    : s_(std::move(settings)), rng_(seed) {
  std::string why;
  if (!s_.valid(&why)) throw std::invalid_argument("plane SLAM settings: " + why);
  gate_ = s_.gate_probability > 0.0
              ? chi_square_quantile(s_.gate_probability, PlaneSlamModel().observation_dim())
              : 0.0;
  filter_ = s_.build_filter(std::make_shared<PlaneSlamModel>());
  filter_->initialize(initial_pose.vector(), s_.initial_covariance());
}

Pose6 PlaneSlam::pose() const {
  return Pose6::from_vector(filter_->pose());
}

// The filter owns (n, d); the semantic map follows it, keeping its normal's side.
void PlaneSlam::sync_map_planes() {
  const Eigen::VectorXd x = filter_->mean();
  const PlaneSlamModel model;
  for (std::size_t i = 0; i < map_.size(); ++i) {
    Eigen::Vector4d v = x.segment<4>(landmark_offset(model, static_cast<int>(i)));
    if (v.head<3>().dot(map_[i].plane.normal) < 0.0) v = -v;
    map_[i].plane = plane_from_vector(v);
  }
}

PlaneSlamStep PlaneSlam::step(const PointCloud& scan, const Pose6& odometry_pose) {
  const auto t_step = Clock::now();
  // 1. The odometry increment (eq. 4.72); 2. the extraction (it does not depend on the prediction).
  const Vector6d u = started_ ? odometry_increment(last_odometry_, odometry_pose) : Vector6d::Zero();
  last_odometry_ = odometry_pose;
  extract(scan);
  PlaneSlamStep out = step(u, s_.process_noise());
  out.seconds = since(t_step);
  return out;
}

const PlaneExtraction& PlaneSlam::extract(const PointCloud& scan) {
  const auto t0 = Clock::now();
  extraction_ = extract_planes(scan, s_.extraction, rng_);
  extraction_seconds_ = since(t0);
  return extraction_;
}

PlaneSlamStep PlaneSlam::step(const Vector6d& u, const Matrix6d& Q) {
  const auto t_step = Clock::now();
  PlaneSlamStep out;
  SlamStepRecord& rec = out.filter;
  const std::vector<PlaneLandmark>& observed = extraction_.landmarks;

  // 1. Prediction with the control u and its covariance Q (eq. 4.72).
  if (started_) {
    const StepResult r = filter_->predict(u, Q);
    rec.predict_status = r.status;
    rec.predict_seconds = r.seconds;
  }
  started_ = true;
  out.extraction_seconds = extraction_seconds_;
  out.extracted = observed.size();
  if (s_.particle_association && dynamic_cast<FastSlam*>(filter_.get())) {
    particle_step(out);
    out.seconds = extraction_seconds_ + since(t_step);
    return out;
  }

  // 3.–4. Transformation of the extracted planes with the predicted pose, association (§4.2.5).
  auto t0 = Clock::now();
  const std::vector<PlaneLandmark> predicted_world = transform_landmarks(observed, to_isometry(pose()));
  const AssociationResult assoc = associate_landmarks(predicted_world, map_, s_.association);
  out.candidates_tested = assoc.candidates_tested;
  out.observation_landmark.assign(observed.size(), -1);
  const Eigen::Matrix4d R = s_.observation_noise();
  std::vector<Eigen::VectorXd> zs;
  std::vector<int> associations;
  for (const LandmarkMatch& m : assoc.matches) {
    const Eigen::Vector4d z = plane_vector(observed[m.observed].plane);
    const int j = static_cast<int>(m.map);
    if (gate_ > 0.0 && !(innovation_distance(*filter_, z, R, j) <= gate_)) {
      ++out.gated;
      continue;
    }
    zs.emplace_back(z);
    associations.push_back(j);
    out.observation_landmark[m.observed] = j;
  }
  out.matched = zs.size();
  out.association_seconds = since(t0);

  // 5. Update with the matched observations (eqs. 4.62–4.66), then augment (eqs. 4.67–4.68).
  if (!zs.empty()) {
    const StepResult r = filter_->update(zs, R, associations);
    rec.update_status = r.status;
    rec.update_seconds = r.seconds;
    if (r.ok()) rec.updated = zs.size();
  }
  for (std::size_t i : assoc.new_landmarks) {
    const int before = filter_->num_landmarks();
    const StepResult r = filter_->augment(plane_vector(observed[i].plane), R);
    keep_first_failure(rec.augment_status, r.status);
    rec.augment_seconds += r.seconds;
    if (filter_->num_landmarks() != before + 1) continue;
    out.observation_landmark[i] = before;
    map_.push_back(PlaneLandmark{});
    map_.back().plane = observed[i].plane;  // side only; sync_map_planes sets (n, d)
    ++rec.augmented;
  }

  // 6. Semantics in the world frame of the updated pose; merged into the associated landmarks.
  sync_map_planes();
  const std::vector<PlaneLandmark> in_world = transform_landmarks(observed, to_isometry(pose()));
  for (std::size_t i = 0; i < in_world.size(); ++i) {
    const int j = out.observation_landmark[i];
    if (j < 0) continue;
    PlaneLandmark& target = map_[static_cast<std::size_t>(j)];
    if (target.inlier_count == 0) {  // just augmented: the observation is its semantic data
      const Plane plane = target.plane;
      target = in_world[i];
      target.plane = plane;
      target.inliers.clear();
    } else if (s_.merge_semantics) {
      target = merge_landmark_semantics(target, in_world[i]);
    }
  }

  rec.pose = filter_->pose();
  if (s_.record_pose_covariance) rec.pose_covariance = filter_->covariance().topLeftCorner(6, 6);
  out.map_size = map_.size();
  out.seconds = extraction_seconds_ + since(t_step);
  return out;
}

PlaneSlamRun run_plane_slam(const PlaneSlamSettings& settings, std::size_t count,
                            const std::function<PointCloud(std::size_t)>& scan,
                            const std::vector<Eigen::Isometry3d>& odometry, const Pose6& initial_pose,
                            std::uint64_t seed, const PlaneSlamStepCallback& on_step,
                            const PlaneSlamMotionSource& motion) {
  if (odometry.size() < count) throw std::invalid_argument("run_plane_slam: fewer odometry poses than scans");
  PlaneSlam slam(settings, initial_pose, seed);
  PlaneSlamRun run;
  for (std::size_t i = 0; i < count; ++i) {
    const auto t_step = Clock::now();
    const PlaneExtraction& extraction = slam.extract(scan(i));
    MotionIncrement m{Vector6d::Zero(), settings.process_noise()};
    if (i > 0) m.u = odometry_increment(to_pose6(odometry[i - 1]), to_pose6(odometry[i]));  // eq. 4.72
    if (motion && i > 0) m = motion(i, extraction, slam.filter(), m);
    run.steps.push_back(slam.step(m.u, m.Q));
    run.steps.back().seconds = since(t_step);
    run.trajectory.push_back(slam.pose());
    if (!run.steps.back().filter.ok()) ++run.failed_steps;
    if (on_step) on_step(i, run.steps.back(), slam.filter());
  }
  run.summary = slam.filter().summary();
  run.map_size = slam.map().size();
  return run;
}

}  // namespace sextant
