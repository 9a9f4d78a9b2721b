// sextant.match()'s registration: register_pair (matchers), the one policy `sextant match` runs too.
#include "match_request.hpp"

#include <utility>

#include "sextant/matchers/matcher_choice.hpp"
#include "sextant/matchers/register_pair.hpp"

namespace sextant::python {

MatchOutcome run_match_request(const PointCloud& reference, const PointCloud& input,
                               const MatchRequest& request) {
  MatchOutcome out;
  PairRegistrationRequest pair;
  pair.matcher = matcher_choice(request.spec.matcher);
  pair.sampler = sampler_factory(request.spec.sampler);
  pair.init = request.init;
  pair.wide_basin = request.wide_basin_retry;
  pair.seed = request.seed;
  PairRegistration registered = register_pair(reference, input, pair);
  out.match = std::move(registered.match);
  out.searched = registered.searched;
  out.search = registered.search;
  out.centre = registered.centre;
  if (registered.searched_without_guess) out.search += " (no init; wide_basin=False: off)";
  return out;
}

}  // namespace sextant::python
