// The registration rows as eval's statistics take them.
#include "registration/report.hpp"

#include <cmath>
#include "kit/row_keys.hpp"
#include "registration/row_keys.hpp"

namespace sextant {

RegistrationSample sample_of(const RunRow& row) {
  RegistrationSample s;
  s.estimate = series_to_isometry(series_or_empty(row, keys::kEstimate));
  s.ground_truth = series_to_isometry(series_or_empty(row, keys::kGroundTruth));
  s.converged = row.value(keys::kConverged) > 0.5;
  s.iterations = static_cast<int>(row.value(keys::kIterations));
  s.seconds = row.value(keys::kSecondsRegistration);
  const double input = row.value(keys::kInputPoints), percent = row.value(keys::kMatchedPercent);
  if (std::isfinite(input) && std::isfinite(percent) && input > 0) {
    s.total_points = static_cast<std::size_t>(input);
    s.matched_points = static_cast<std::size_t>(std::llround(percent / 100.0 * input));
  }
  return s;
}

std::optional<RegistrationSample> odometry_sample_of(const RunRow& row) {
  const auto it = row.series.find(keys::kOdometry);
  const auto gt = row.series.find(keys::kGroundTruth);
  if (it == row.series.end() || gt == row.series.end()) return std::nullopt;
  RegistrationSample s;
  s.estimate = series_to_isometry(it->second);
  s.ground_truth = series_to_isometry(gt->second);
  return s;
}

RegistrationStatsSettings stats_settings(const RegistrationParams& params) {
  RegistrationStatsSettings s;
  s.axes = params.axes;
  s.success = thesis_success_criterion(params.success);
  return s;
}

}  // namespace sextant
