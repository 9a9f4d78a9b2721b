#pragma once
// Hybrid SLAM's motion source (the thesis' future work §7.2): FbML-NDT between consecutive
// scans, on the plane extraction the SLAM step already made. Its sample is the cell-plane inliers
// of the current scan (Table 3.2: the feature extraction process of FbML-NDT is the first stage of
// the plane extraction, §4.1), matched by ML-NDT against the previous scan from the odometry
// increment. The relative pose T (previous ← current) and Σ = noise_scale · H⁻¹ (eq. 3.50) become
// the control u of eq. (4.72) and its covariance Q (filters/relative_motion.hpp).
// The odometry's own increment and Q are used instead — and the step counted as a fallback — when
// the sample does not constrain all six parameters (sample_constraints.hpp), the registration did
// not converge, H is not positive definite, or matcher and odometry disagree beyond the alarm
// thresholds (the rule of Table 3.3's KF, §5.1.3.2).
#include <string>

#include "kit/plane_slam_params.hpp"
#include "sextant/core/point_cloud.hpp"
#include "sextant/features/extraction.hpp"
#include "sextant/filters/relative_motion.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/sample_constraints.hpp"

namespace sextant {

struct HybridMotion {
  MotionIncrement motion;  ///< what the filter predicts with
  bool matched = false;    ///< the matcher's increment was used (false: the odometry's, see reason)
  std::string reason;      ///< why not ("" when matched)
  double seconds = 0.0;    ///< registration only: reference model + constraint check + align
};

class FbmlndtMotion {
 public:
  FbmlndtMotion(const YAML::Node& matcher, const HybridParams& params, const std::string& file);

  /// The motion from scan `previous` to `current`, whose extraction is `extraction`, starting at
  /// the filter's pose `from`; `odometry` is the odometry's increment and Q (initial guess, fallback).
  HybridMotion motion(const PointCloud& previous, const PointCloud& current,
                      const PlaneExtraction& extraction, const Vector6d& from,
                      const MotionIncrement& odometry);

 private:
  MlndtMatcher matcher_;
  HybridParams params_;
  ConstraintThresholds constraints_;
};

}  // namespace sextant
