#pragma once
// The one interface every scan matcher implements (ours and PCL's peers):
//
//   auto matcher = std::make_unique<MlndtMatcher>(settings);           // or matcher_choice.hpp;
//                                                                       // by name from YAML: yaml.hpp
//   matcher->set_reference(reference);                                  // grids, trees
//   RegistrationResult r = matcher->align(sampled_input, initial_guess);
//
// `align` maps input points into the reference frame: p_ref ≈ r.T · p_input. The input is what
// gets matched (already sampled, see sampler.hpp).
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/matchers/registration_result.hpp"

namespace sextant {

class Matcher {
 public:
  virtual ~Matcher() = default;
  virtual std::string name() const = 0;
  /// Builds the reference model (cell grids, layer pyramid, k-d tree). Call before align().
  virtual void set_reference(const PointCloud& reference) = 0;
  /// Instead of set_reference: takes the reference model `built` holds, when this matcher would build
  /// the same one from the same reference (the caller's promise: `built` was last given the reference
  /// this matcher is to use). False, and nothing changed, when it cannot; then call set_reference.
  virtual bool share_reference(const Matcher& /*built*/) { return false; }
  /// Aligns `input` to the reference from `initial`; never throws for bad data (status in result).
  virtual RegistrationResult align(const PointCloud& input, const Eigen::Isometry3d& initial) = 0;
};

}  // namespace sextant
