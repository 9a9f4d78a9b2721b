// Matchers and samplers for register_pair and odometry (matcher_choice.hpp).
#include "sextant/matchers/matcher_choice.hpp"

#include <stdexcept>

#include "sextant/matchers/judged_matcher.hpp"

namespace sextant {

namespace {

template <class Spec>
const Spec& checked_spec(const Spec& spec) {
  std::string why;
  if (!spec.valid(&why)) throw std::invalid_argument("invalid " + spec.name() + " settings: " + why);
  return spec;
}

bool wide_basin_enabled(const MatcherSpec& spec) {
  if (const MlndtSettings* s = spec.get<MlndtSettings>()) return s->wide_basin.enabled;
  if (const FbmlndtSettings* s = spec.get<FbmlndtSettings>()) return s->mlndt.wide_basin.enabled;
  return false;
}

}  // namespace

MatcherChoice matcher_choice(const MatcherSpec& spec) {
  MatcherChoice c;
  c.name = checked_spec(spec).name();
  c.make = [spec] { return judged(make_matcher(spec)); };
  if (spec.traits().has_wide_basin) {
    c.make_wide = [wide = with_wide_basin(spec)] { return make_matcher(wide); };
    c.own_wide_basin = wide_basin_enabled(spec);
  }
  return c;
}

SamplerFactory sampler_factory(const SamplerSpec& spec) {
  checked_spec(spec);
  return [spec] { return make_sampler(spec); };
}

}  // namespace sextant
