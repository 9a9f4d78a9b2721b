#pragma once
// One odometry step's registrations (odometry.cpp): the first try from the guess, and the recovery of
// an untrusted step with the wide basin from the guess and the other starts.
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/odometry/odometry.hpp"

namespace sextant::odometry_detail {

/// The matcher and sampler of one worker, and the wide-basin matcher it recovers with.
class StepWorker {
 public:
  explicit StepWorker(const OdometrySettings& s);

  /// The first registration from `guess`, assessed on its own (absolute checks).
  OdometryStep first_try(const PointCloud& reference, const PointCloud& input, const Eigen::Isometry3d& guess,
                         std::uint64_t seed);

  /// An untrusted step: the wide basin from each of `starts` (the guess first) until a registration
  /// is trusted; when none is, the step chains one of the registrations whose only flaw is their fit
  /// (suspect_choice.hpp), else `starts.back()` (the last trusted motion), and stays untrusted. The sequence
  /// check only triggers this search: the wide basin's answer is judged on its own
  /// (registration_quality.hpp), since a step may rightly overlap less than its neighbours (a corner, an open
  /// space; measured on the campus: right poses 0.70 where the median is 0.87). A first registration
  /// that passed its own checks stays a candidate: a trusted recovery more than 1 m or 5° from it is a
  /// second answer, and the step is then chained as the least suspect and says it is ambiguous.
  void recover(OdometryStep& step, const PointCloud& reference, const PointCloud& input,
               const std::vector<Eigen::Isometry3d>& starts, std::uint64_t seed);

 private:
  OdometryStep to_step(const PairMatch& m, const PointCloud& reference, const Eigen::Isometry3d& guess) const;

  std::unique_ptr<Matcher> matcher_;
  /// What recovers an untrusted step: the matcher with its wide basin (mlndt, fbmlndt), else the
  /// matcher itself from the other starts; null when recovery is off.
  std::unique_ptr<Matcher> recovery_;
  bool wide_basin_ = false;
  std::unique_ptr<Sampler> sampler_;
  const OdometrySettings& settings_;
  const PointCloud* matcher_reference_ = nullptr;  ///< what `matcher_` was last given (its model's source)
};

}  // namespace sextant::odometry_detail
