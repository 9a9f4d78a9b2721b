// sextant.match()'s registration, the same calls in the same order as `sextant match`
// (match_request.hpp says which choices; cmd_match.cpp's run_match is the original).
#include "match_request.hpp"

#include <utility>

#include "sextant/core/error.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/mlndt_presets.hpp"
#include "sextant/matchers/sampler.hpp"

namespace sextant::python {
namespace {

constexpr char kWhere[] = "match() settings";

bool has_presets(const std::string& method) {
  return method == "mlndt" || method == "fbmlndt";
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
  const YAML::Node settings = matcher_settings(request.method, request.preset, request.settings, &out.preset);
  const auto sampler = make_sampler(request.sampling, request.sampler_settings, "match() sampler settings");
  const Eigen::Isometry3d initial = request.init.value_or(Eigen::Isometry3d::Identity());
  const std::optional<YAML::Node> wide = with_wide_basin(request.method, settings);
  const bool has_own_wide_basin = settings["wide_basin"].IsDefined();
  const bool search_first = !request.init && request.wide_basin_retry && wide.has_value();
  auto matcher = make_matcher(request.method, search_first ? *wide : settings, kWhere);
  Rng rng(request.seed);
  out.match = match_pair(*matcher, *sampler, reference, input, initial, rng);
  out.searched = has_own_wide_basin || search_first;
  out.search = out.searched ? "wide basin" : "from the guess";
  if (search_first) out.search += " (no init; wide_basin=False: off)";
  if (!out.match.result.quality.trusted() && !out.searched && request.wide_basin_retry && wide) {
    const auto wide_matcher = make_matcher(request.method, *wide, kWhere);
    Rng again(request.seed);
    PairMatch retry = match_pair(*wide_matcher, *sampler, reference, input, initial, again);
    const std::string first = to_string(out.match.result.quality.trust);
    if (retry.result.quality.trusted()) {
      out.match = std::move(retry);
      out.searched = true;
      out.search += ", " + first + ": recovered by the wide basin";
    } else {
      out.search += ", " + first + ": the wide basin found no trusted pose either";
    }
  }
  return out;
}

}  // namespace sextant::python
