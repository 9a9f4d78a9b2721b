#pragma once
// The SLAM driver: runs any Filter over a sequence of (control, observed landmarks) steps and
// returns the estimated trajectory with per-step statuses and times. Associations come with the
// observations as landmark ids (ground truth, or the features module's semantic association
// computed with the predicted pose); an id seen for the first time is augmented (eq. 4.55).
// Per step: the motion update with u (eq. 4.72 for plane SLAM; none for an empty u, e.g. a first
// scan taken at the initial pose), the measurement update with the known landmarks' observations
// (eq. 4.64), the augmentation with the new ones (eqs. 4.57–4.58); then the callback, if any, sees
// the step's record and the filter (what a caller records beyond the record: joint_covariance(),
// diagnostics()). Plane SLAM with extraction and semantic association: run_plane_slam
// (plane_slam.hpp), the same steps behind PlaneSlam's front end.
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sextant/filters/filter.hpp"

namespace sextant {

struct SlamObservation {
  Eigen::VectorXd z;  ///< observation (model().observation_dim())
  int landmark = -1;  ///< the caller's id of the observed landmark (≥ 0)
};

struct SlamStepInput {
  Eigen::VectorXd u;                          ///< control (odometry increment); empty: no motion update
  std::vector<SlamObservation> observations;  ///< may be empty
};

struct SlamStepRecord {
  Eigen::VectorXd pose;             ///< estimated pose after the step
  Eigen::MatrixXd pose_covariance;  ///< its covariance (empty for information filters unless asked)
  StepStatus predict_status = StepStatus::kOk;
  StepStatus update_status = StepStatus::kOk;
  StepStatus augment_status = StepStatus::kOk;
  std::size_t updated = 0;    ///< observations of known landmarks
  std::size_t augmented = 0;  ///< new landmarks
  double predict_seconds = 0.0;
  double update_seconds = 0.0;
  double augment_seconds = 0.0;
  bool ok() const {
    return predict_status == StepStatus::kOk && update_status == StepStatus::kOk &&
           augment_status == StepStatus::kOk;
  }
};

struct SlamRunSettings {
  bool record_pose_covariance = true;  ///< costs O(n³) per step for information filters
  bool valid(std::string* why) const;
};

struct SlamRunResult {
  std::vector<SlamStepRecord> steps;
  FilterSummary summary;              ///< the filter's counts over the run
  std::size_t failed_steps = 0;       ///< steps with any non-ok status
  std::map<int, int> landmark_index;  ///< caller id → filter landmark index
};

/// Called after every step with its index in `steps`, its record and the filter after it.
using SlamStepCallback =
    std::function<void(std::size_t step, const SlamStepRecord& record, const Filter& filter)>;

/// Runs `filter` (already initialised) over `steps`. Q: control noise, R: observation noise;
/// `known` maps caller ids to landmarks already in the filter; `on_step` (optional) after each step.
SlamRunResult run_slam(Filter& filter, const std::vector<SlamStepInput>& steps, const Eigen::MatrixXd& Q,
                       const Eigen::MatrixXd& R, const SlamRunSettings& settings = {},
                       std::map<int, int> known = {}, const SlamStepCallback& on_step = {});

}  // namespace sextant
