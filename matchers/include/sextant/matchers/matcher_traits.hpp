#pragma once
// What the code needs to know of a matcher by its name, in one table, instead of sets of names spelled
// out where each rule is applied:
//
//   if (matcher_traits(method).has_presets) …   // `preset:` and `solver:` apply
#include <string>

namespace sextant {

struct MatcherTraits {
  /// Its results carry their own trust evidence (the last layer's fit and Hessian); the others are
  /// judged by the default ML-NDT's last layer (judged_matcher.hpp)
  bool judges_itself = false;
  /// The ML-NDT settings presets (`preset:` default, thesis, outdoor) and a `solver:` choice
  bool has_presets = false;
  /// The wide basin (`wide_basin:`, mlndt_global_init.hpp): a search, and odometry's recovery
  bool has_wide_basin = false;
  /// A layer pyramid (the adaptive start layer of the registration experiments)
  bool layer_pyramid = false;
  /// Odometry registers only what both sensors see by default: measured better for ML-NDT on the campus
  /// and both MulRan stretches, not for the others (docs/matcher_defaults.md, "Registering only what
  /// both scans can see")
  bool common_view_by_default = false;
};

/// The traits of the matcher named `name` (matcher_names(): mlndt, fbmlndt, ndt, icp_p2p, icp_p2l,
/// pcl_ndt, pcl_icp, pcl_gicp); none of them for another name.
MatcherTraits matcher_traits(const std::string& name);

}  // namespace sextant
