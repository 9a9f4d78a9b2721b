#pragma once
// A SLAM driver: runs any Filter over a sequence of (control, observed landmarks) steps and
// returns the estimated trajectory with per-step statuses and times. Associations come with the
// observations as landmark ids (ground truth, or the features module's semantic association
// computed with the predicted pose); an id seen for the first time is augmented (eq. 4.55).
#include <cstddef>
#include <map>
#include <vector>

#include <Eigen/Core>

#include "sextant/filters/filter.hpp"

namespace sextant {

struct SlamObservation {
  Eigen::VectorXd z;  ///< observation (model().observation_dim())
  int landmark = -1;  ///< the caller's id of the observed landmark (≥ 0)
};

struct SlamStepInput {
  Eigen::VectorXd u;                          ///< control (odometry increment)
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

/// Runs `filter` (already initialised) over `steps`. Q: control noise, R: observation noise;
/// `known` maps caller ids to landmarks already in the filter.
SlamRunResult run_slam(Filter& filter, const std::vector<SlamStepInput>& steps, const Eigen::MatrixXd& Q,
                       const Eigen::MatrixXd& R, const SlamRunSettings& settings = {},
                       std::map<int, int> known = {});

}  // namespace sextant
