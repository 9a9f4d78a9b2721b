#include "sextant/filters/slam_runner.hpp"

namespace sextant {

bool SlamRunSettings::valid(std::string* /*why*/) const {
  return true;
}

SlamRunResult run_slam(Filter& filter, const std::vector<SlamStepInput>& steps, const Eigen::MatrixXd& Q,
                       const Eigen::MatrixXd& R, const SlamRunSettings& settings, std::map<int, int> known,
                       const SlamStepCallback& on_step) {
  SlamRunResult result;
  result.landmark_index = std::move(known);
  const int p = filter.model().pose_dim();
  for (const SlamStepInput& step : steps) {
    SlamStepRecord record;
    if (step.u.size() > 0) {  // motion update (eq. 4.72 for plane SLAM)
      const StepResult predicted = filter.predict(step.u, Q);
      record.predict_status = predicted.status;
      record.predict_seconds = predicted.seconds;
    }

    std::vector<Eigen::VectorXd> zs;
    std::vector<int> associations;
    std::vector<const SlamObservation*> fresh;
    for (const SlamObservation& obs : step.observations) {
      const auto it = result.landmark_index.find(obs.landmark);
      if (it == result.landmark_index.end()) {
        fresh.push_back(&obs);
      } else {
        zs.push_back(obs.z);
        associations.push_back(it->second);
      }
    }
    if (!zs.empty()) {
      const StepResult updated = filter.update(zs, R, associations);
      record.update_status = updated.status;
      record.update_seconds = updated.seconds;
      record.updated = zs.size();
    }
    for (const SlamObservation* obs : fresh) {
      if (result.landmark_index.count(obs->landmark)) continue;  // seen twice in one step
      const int before = filter.num_landmarks();
      const StepResult augmented = filter.augment(obs->z, R);
      record.augment_seconds += augmented.seconds;
      if (filter.num_landmarks() > before) {  // grown even when the new covariance is unhealthy
        result.landmark_index[obs->landmark] = filter.num_landmarks() - 1;
        ++record.augmented;
      }
      if (!augmented.ok()) record.augment_status = augmented.status;
    }
    const Eigen::VectorXd mean = filter.mean();
    record.pose = mean.head(p);
    if (settings.record_pose_covariance) record.pose_covariance = filter.covariance().topLeftCorner(p, p);
    if (!record.ok()) ++result.failed_steps;
    if (on_step) on_step(result.steps.size(), record, filter);
    result.steps.push_back(std::move(record));
  }
  result.summary = filter.summary();
  return result;
}

}  // namespace sextant
