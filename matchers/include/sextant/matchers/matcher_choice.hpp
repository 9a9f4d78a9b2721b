#pragma once
// A matcher and a sampler for register_pair and odometry, from their specs (matcher_spec.hpp): factories
// that build fresh instances of one configuration (each worker, each retry its own), and the wide-basin
// variant a registration retries with (register_pair.hpp, odometry.hpp). Matchers that do not judge
// their own poses come judged by the default ML-NDT's last layer (judged_matcher.hpp).
//
//   MlndtSettings s;                       // the library's defaults: the `default` preset
//   s.pyramid.layers = 3;
//   PairRegistrationRequest request;
//   request.matcher = matcher_choice(s);
//   request.sampler = sampler_factory(GridSamplerSettings{});
//
// The same specs read from YAML (with presets, file/line/key errors): read_matcher_spec of
// matchers/yaml.hpp.
#include <functional>
#include <memory>
#include <string>

#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/matcher_spec.hpp"
#include "sextant/matchers/sampler.hpp"

namespace sextant {

using MatcherFactory = std::function<std::unique_ptr<Matcher>()>;
using SamplerFactory = std::function<std::unique_ptr<Sampler>()>;

struct MatcherChoice {
  std::string name;     ///< the matcher's name: mlndt, fbmlndt, ndt, icp_p2p, icp_p2l, pcl_ndt, …
  MatcherFactory make;  ///< the matcher as configured
  /// The same matcher with the wide basin on (with_wide_basin of matcher_spec.hpp); empty for a
  /// matcher without a wide basin
  MatcherFactory make_wide;
  bool own_wide_basin = false;  ///< `make` searches with the wide basin already
};

/// std::invalid_argument when the settings are not valid.
MatcherChoice matcher_choice(const MatcherSpec& spec);
SamplerFactory sampler_factory(const SamplerSpec& spec);

}  // namespace sextant
