#pragma once
// sextant.match()'s registration: register_pair (matchers/register_pair.hpp), the policy `sextant match`
// runs too: the wide basin without a guess, a retry with it of an untrusted result with one. The
// matcher and sampler are read as the CLI reads them (pipeline/matcher_request.hpp).
// No Python here: run_match_request runs with the GIL released.
#include <cstdint>
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/matcher_spec.hpp"

namespace sextant::python {

struct MatchRequest {
  RegistrationSpec spec;
  std::optional<Eigen::Isometry3d> init;  ///< the CLI's --init; none: the identity, searched
  bool wide_basin_retry = true;           ///< false: the CLI's --no-wide-basin
  std::uint64_t seed = 1;                 ///< the CLI's --seed
};

struct MatchOutcome {
  PairMatch match;
  bool searched = false;  ///< the result came from the wide basin
  std::string search;     ///< how, in the CLI's words ("wide basin", "from the guess", …)
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< the point registered about (register_pair.hpp)
};

/// Registers `input` against `reference` as `sextant match` does (see above).
MatchOutcome run_match_request(const PointCloud& reference, const PointCloud& input,
                               const MatchRequest& request);

}  // namespace sextant::python
