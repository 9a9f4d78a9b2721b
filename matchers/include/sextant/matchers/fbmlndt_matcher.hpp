#pragma once
// FbML-NDT (§3.3.1.3, Table 3.2): only the plane inliers of the input scan (feature_based_sampler.hpp)
// are matched by ML-NDT.
//
//   matcher `fbmlndt`: the mlndt keys, plus `features:` (plane extraction settings) and `seed`
//                      (the RANSAC stream, fixed per align call so results are deterministic).
//                      align() takes the whole input scan and samples it with fbs itself.
//                      It fails safe: `fallback` (gbs | add_gbs | none), `constraints:` (thresholds
//                      of sample_constraints.hpp) and `fallback_gbs:` (GBS settings) decide what
//                      happens when the feature sample cannot constrain all six parameters.
#include <cstdint>
#include <memory>
#include <string>

#include "sextant/matchers/feature_based_sampler.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/sample_constraints.hpp"
#include "sextant/matchers/samplers.hpp"

namespace sextant {

/// What FbML-NDT does when the feature sample is degenerate (sample_constraints.hpp).
enum class FbsFallback {
  kGbs,     ///< match a GBS sample of the whole scan instead (default: what mlndt itself matches)
  kAddGbs,  ///< match the feature points plus a GBS sample (the planes still dominate the score)
  kNone,    ///< match the feature sample anyway (the thesis' FbML-NDT; the check is still recorded)
};

struct FbmlndtSettings {
  MlndtSettings mlndt;               ///< the registration process (Table 3.2)
  PlaneExtractionSettings features;  ///< the feature extraction process
  std::uint64_t seed = 1;            ///< RANSAC seed used at every align() call
  FbsFallback fallback = FbsFallback::kGbs;
  ConstraintThresholds constraints;  ///< when a feature sample counts as degenerate
  GridSamplerSettings fallback_gbs;  ///< the GBS sample added or used on fallback
  /// Check the result on the GBS sample: plane points can slide along their planes, the rest of the
  /// scene cannot (docs/matcher_defaults.md, "FbML-NDT is checked on GBS points"). The last layer
  /// refines the result with GBS points; a trusted refinement is the result, else ML-NDT on the GBS
  /// points from the initial guess is, when trusted (recorded in `fallback`). YAML `verify`; unset: on
  /// exactly when the ML-NDT settings' refine_first is (off in the thesis preset)
  bool verify = true;
  bool valid(std::string* why) const;
};

/// ML-NDT whose input points are the fbs sample of the input scan.
class FbmlndtMatcher final : public Matcher {
 public:
  explicit FbmlndtMatcher(FbmlndtSettings settings = {});
  std::string name() const override { return "fbmlndt"; }
  void set_reference(const PointCloud& reference) override { mlndt_.set_reference(reference); }
  /// `input` is the whole scan; an input without planes gives a result with converged = false.
  RegistrationResult align(const PointCloud& input, const Eigen::Isometry3d& initial) override;
  /// Points of the last input that were matched (the fbs sample, plus GBS points on fallback).
  std::size_t last_sample_size() const { return last_sample_size_; }
  /// The constraint check of the last input's feature sample.
  const ConstraintCheck& last_check() const { return last_check_; }

 private:
  /// settings_.verify: the result checked, and replaced when need be, on a GBS sample of `input`.
  void verify_on_gbs(const PointCloud& input, const Eigen::Isometry3d& initial, Rng& rng,
                     RegistrationResult& result, std::string& fallback);
  FbmlndtSettings settings_;
  MlndtMatcher mlndt_;
  std::size_t last_sample_size_ = 0;
  ConstraintCheck last_check_;
};

}  // namespace sextant
