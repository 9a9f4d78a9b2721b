// sextant.match()'s registration: the CLI's preset rule, then register_pair (matchers), the one
// policy `sextant match` runs too.
#include "match_request.hpp"

#include <utility>

#include "sextant/core/error.hpp"
#include "sextant/matchers/matcher_traits.hpp"
#include "sextant/matchers/register_pair.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant::python {
namespace {

constexpr char kWhere[] = "match() settings";

bool has_presets(const std::string& method) {
  return matcher_traits(method).has_presets;
}

}  // namespace

YAML::Node matcher_settings(const std::string& method, const std::string& preset, const YAML::Node& settings,
                            std::string* applied) {
  YAML::Node out = settings.IsMap() ? YAML::Clone(settings) : YAML::Node(YAML::NodeType::Map);
  if (!preset.empty() && !has_presets(method))
    throw InputError("preset", "", "presets are settings of mlndt and fbmlndt, not of '" + method + "'");
  // As the CLI: the map's own `preset:` wins over the argument; its other keys override the preset's.
  if (has_presets(method) && !out["preset"].IsDefined()) out["preset"] = preset.empty() ? "default" : preset;
  if (applied) *applied = has_presets(method) ? out["preset"].as<std::string>("") : "";
  return out;
}

MatchOutcome run_match_request(const PointCloud& reference, const PointCloud& input,
                               const MatchRequest& request) {
  MatchOutcome out;
  PairRegistrationRequest pair;
  pair.matcher =
      matcher_choice(request.method,
                     matcher_settings(request.method, request.preset, request.settings, &out.preset), kWhere);
  pair.sampler = sampler_factory(request.sampling, request.sampler_settings, "match() sampler settings");
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
