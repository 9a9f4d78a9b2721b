#pragma once
// A matcher and a sampler chosen in code, from the plain settings structs (no YAML): factories that
// build fresh instances of one configuration (each worker, each retry its own), and the wide-basin
// variant a registration retries with (register_pair.hpp, odometry.hpp). Matchers that do not judge
// their own poses come judged by the default ML-NDT's last layer (judged_matcher.hpp).
//
//   MlndtSettings s;                       // the library's defaults: the `default` preset
//   s.pyramid.layers = 3;
//   PairRegistrationRequest request;
//   request.matcher = matcher_choice(s);
//   request.sampler = sampler_factory(GridSamplerSettings{});
//
// The same choice read from YAML by registry name (with presets, file/line/key errors) is
// matcher_choice(name, node, file) of matchers/yaml.hpp.
#include <functional>
#include <memory>
#include <string>

#include "sextant/matchers/fbmlndt_matcher.hpp"
#include "sextant/matchers/icp.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/ndt_matcher.hpp"
#include "sextant/matchers/pcl_peers.hpp"
#include "sextant/matchers/sampler.hpp"
#include "sextant/matchers/samplers.hpp"

namespace sextant {

using MatcherFactory = std::function<std::unique_ptr<Matcher>()>;
using SamplerFactory = std::function<std::unique_ptr<Sampler>()>;

struct MatcherChoice {
  std::string name;     ///< the matcher's name: mlndt, fbmlndt, ndt, icp_p2p, icp_p2l, pcl_ndt, …
  MatcherFactory make;  ///< the matcher as configured
  /// The same matcher with the wide basin on (mlndt and fbmlndt: their own wide-basin settings when
  /// enabled, else the defaults); empty for a matcher without a wide basin
  MatcherFactory make_wide;
  bool own_wide_basin = false;  ///< `make` searches with the wide basin already
};

/// The settings are used as given: check them with valid() first (the YAML readers do).
MatcherChoice matcher_choice(const MlndtSettings& settings);
MatcherChoice matcher_choice(const FbmlndtSettings& settings);
MatcherChoice matcher_choice(const NdtSettings& settings);
MatcherChoice matcher_choice(IcpObjective objective, const IcpSettings& settings);
MatcherChoice matcher_choice(const PclNdtSettings& settings);
MatcherChoice matcher_choice(const PclIcpSettings& settings);
MatcherChoice matcher_choice(const PclGicpSettings& settings);

SamplerFactory sampler_factory(const GridSamplerSettings& settings);
SamplerFactory sampler_factory(const RegularSamplerSettings& settings);
SamplerFactory sampler_factory(const RandomSamplerSettings& settings);
/// `fbs`: the plane inliers of per-cell RANSAC.
SamplerFactory sampler_factory(const PlaneExtractionSettings& settings);
/// `all`: every point.
SamplerFactory all_points_sampler_factory();

}  // namespace sextant
