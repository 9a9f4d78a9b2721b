#pragma once
// The trust checks for matchers that do not judge their own poses (issue 22). ML-NDT and FbML-NDT
// report, at their final pose, the last layer's matched points, mean matched term against its
// prediction and Hessian: the overlap, fit and constraint of registration_quality.hpp. ICP, P2D-NDT
// and the PCL peers report no fit and (most) no Hessian, so on their own report only their overlap by
// their own correspondences could be checked, and a pose slid along a road keeps its points within
// their correspondence distance (docs/matcher_defaults.md, "Every matcher's poses judged on one
// model"). A JudgedMatcher registers with the matcher it wraps and scores the result's pose on the
// default ML-NDT's last layer, as ML-NDT scores its own: one model judges every matcher's poses, the
// one the thresholds were measured on. The pose, score, H and seconds stay the matcher's; the
// judge's model is built with the reference. `sextant match`, `sextant odometry` and the Python
// module judge every matcher so (matcher_choice); the experiments run the matchers bare.
//
//   std::unique_ptr<Matcher> m = judged(make_icp(IcpObjective::kPointToPlane, settings));
#include <memory>
#include <string>

#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"

namespace sextant {

class JudgedMatcher final : public Matcher {
 public:
  explicit JudgedMatcher(std::unique_ptr<Matcher> matcher);
  std::string name() const override { return matcher_->name(); }
  void set_reference(const PointCloud& reference) override;
  /// The matcher's result with matched_points, mean_matched_score, predicted_matched_score and
  /// constraint_hessian those of the judge's last layer at the result's pose (left as the matcher
  /// gave them where the judge models nothing of the reference).
  RegistrationResult align(const PointCloud& input, const Eigen::Isometry3d& initial) override;

 private:
  std::unique_ptr<Matcher> matcher_;
  MlndtMatcher judge_;  ///< the default ML-NDT without its precision stage (only its layers judge)
};

/// `matcher` as it is when it judges itself (matcher_traits.hpp), else in a JudgedMatcher.
std::unique_ptr<Matcher> judged(std::unique_ptr<Matcher> matcher);

}  // namespace sextant
