#include "sextant/pipeline/trajectory_accuracy.hpp"

#include <iomanip>
#include <sstream>

#include "sextant/core/units.hpp"
#include "sextant/pipeline/json.hpp"

namespace sextant {

TrajectoryAccuracy trajectory_accuracy(const TrajectoryEvaluation& e) {
  TrajectoryAccuracy a;
  a.ate_translation = e.ate.translation.rms;
  a.ate_rotation = e.ate.rotation.rms;
  a.rpe_translation = e.rpe.translation.rms;
  a.rpe_rotation = e.rpe.rotation.rms;
  if (e.drift.status.ok && e.drift.segments > 0) {
    a.drift_segments = e.drift.segments;
    a.drift_percent = 100.0 * e.drift.translation;
    a.drift_deg_per_100m = 100.0 * kDegPerRad * e.drift.rotation;
  }
  return a;
}

std::optional<TrajectoryAccuracy> trajectory_accuracy(const std::vector<Eigen::Isometry3d>& estimate,
                                                      const std::vector<Eigen::Isometry3d>& truth,
                                                      std::string* why) {
  const TrajectoryEvaluation e = evaluate_trajectory(estimate, truth);
  if (!e.status.ok) {
    if (why) *why = e.status.message;
    return std::nullopt;
  }
  return trajectory_accuracy(e);
}

std::string accuracy_line(const TrajectoryAccuracy& a, const std::string& rpe_per) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << "ATE " << a.ate_translation << " m / " << std::setprecision(2)
      << a.ate_rotation * kDegPerRad << "°, RPE " << std::setprecision(3) << a.rpe_translation << " m / "
      << std::setprecision(2) << a.rpe_rotation * kDegPerRad << "° per " << rpe_per << ", drift ";
  if (a.drift_segments == 0) {
    out << "n/a (path shorter than 100 m)";
  } else {
    out << a.drift_percent << " % / " << std::setprecision(3) << a.drift_deg_per_100m << "°/100 m ("
        << a.drift_segments << " segments)";
  }
  return out.str();
}

Json accuracy_json(const TrajectoryAccuracy& a) {
  const bool drift = a.drift_segments > 0;
  return {{"ate_m", json_value(a.ate_translation)},
          {"ate_deg", json_value(a.ate_rotation * kDegPerRad)},
          {"rpe_m", json_value(a.rpe_translation)},
          {"rpe_deg", json_value(a.rpe_rotation * kDegPerRad)},
          {"drift_segments", a.drift_segments},
          {"drift_percent", drift ? json_value(a.drift_percent) : Json()},
          {"drift_deg_per_100m", drift ? json_value(a.drift_deg_per_100m) : Json()}};
}

}  // namespace sextant
