#pragma once
// A matcher that answers by script, for the tests of the trust and recovery rules (step_worker.hpp,
// register_pair.hpp): each start gets the answer the script gives it, keyed by its forward metres.
#include <cstddef>
#include <map>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/registration_result.hpp"

namespace sextant::test {

/// A pose `x` metres forward.
inline Eigen::Isometry3d metres_ahead(double x) {
  return Eigen::Isometry3d(Eigen::Translation3d(x, 0.0, 0.0));
}

/// A converged registration at `T` that matched `overlap` of its `points` and fits `fit` × the
/// prediction, every direction equally constrained.
inline RegistrationResult scripted_answer(const Eigen::Isometry3d& T, std::size_t points, double overlap,
                                          double fit) {
  RegistrationResult r;
  r.T = T;
  r.converged = true;
  r.why = Termination::kConverged;
  r.H = Matrix6d::Identity();
  r.input_points = points;
  r.matched_points = static_cast<std::size_t>(overlap * static_cast<double>(points));
  r.predicted_matched_score = 3.0;
  r.mean_matched_score = 3.0 * fit;
  return r;
}

/// What a registration from a start (keyed by its forward metres) answers: the pose, its overlap and
/// fit, and optionally a second solution the same registration reached (an alternative).
struct Scripted {
  double x = 0.0, overlap = 0.9, fit = 1.0;
  double alternative_x = 0.0, alternative_fit = 0.0;  ///< alternative_fit 0: none
};

class ScriptedMatcher final : public Matcher {
 public:
  explicit ScriptedMatcher(std::map<double, Scripted> script) : script_(std::move(script)) {}
  std::string name() const override { return "scripted"; }
  void set_reference(const PointCloud& /*reference*/) override {}
  RegistrationResult align(const PointCloud& input, const Eigen::Isometry3d& initial) override {
    const Scripted& s = script_.at(initial.translation().x());
    RegistrationResult r = scripted_answer(metres_ahead(s.x), input.size(), s.overlap, s.fit);
    if (s.alternative_fit > 0.0)
      r.alternatives.push_back(
          scripted_answer(metres_ahead(s.alternative_x), input.size(), s.overlap, s.alternative_fit));
    return r;
  }

 private:
  std::map<double, Scripted> script_;
};

/// A flat scan of 100 points on a 1 m grid, at the sensor's height (none above its horizon).
inline PointCloud scripted_cloud() {
  PointCloud c;
  for (int i = 0; i < 100; ++i) c.push_back({static_cast<float>(i % 10), static_cast<float>(i / 10), 0.f});
  return c;
}

/// A scan of 100 points, half of them above the sensor's horizon.
inline PointCloud scan_above_and_below() {
  PointCloud c = scripted_cloud();
  for (std::size_t i = 0; i < c.size(); i += 2) c[i].z() = 1.0f;
  return c;
}

}  // namespace sextant::test
