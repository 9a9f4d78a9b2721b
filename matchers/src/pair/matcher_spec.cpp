// The catalogue of matchers and samplers by value (matcher_spec.hpp).
#include "sextant/matchers/matcher_spec.hpp"

#include <algorithm>

namespace sextant {

namespace {

template <template <class> class Kind, class... Settings>
std::vector<std::string> sorted_names(const std::variant<Settings...>*) {
  std::vector<std::string> names{Kind<Settings>::kName...};
  std::sort(names.begin(), names.end());
  return names;
}

template <class... Settings>
MatcherTraits traits_by_name(const std::string& name, const std::variant<Settings...>*) {
  MatcherTraits traits;
  ((name == MatcherKind<Settings>::kName ? void(traits = MatcherKind<Settings>::kTraits) : void()), ...);
  return traits;
}

MlndtSettings wide_basin_on(MlndtSettings s) {
  if (!s.wide_basin.enabled) {
    s.wide_basin = WideBasinSettings{};
    s.wide_basin.enabled = true;
  }
  return s;
}

}  // namespace

std::string MatcherSpec::name() const {
  return std::visit(
      [](const auto& s) -> std::string { return MatcherKind<std::decay_t<decltype(s)>>::kName; }, settings);
}

MatcherTraits MatcherSpec::traits() const {
  return std::visit([](const auto& s) { return MatcherKind<std::decay_t<decltype(s)>>::kTraits; }, settings);
}

bool MatcherSpec::valid(std::string* why) const {
  return std::visit([why](const auto& s) { return s.valid(why); }, settings);
}

std::string SamplerSpec::name() const {
  return std::visit(
      [](const auto& s) -> std::string { return SamplerKind<std::decay_t<decltype(s)>>::kName; }, settings);
}

bool SamplerSpec::valid(std::string* why) const {
  return std::visit([why](const auto& s) { return s.valid(why); }, settings);
}

std::vector<std::string> matcher_names() {
  return sorted_names<MatcherKind>(static_cast<MatcherSettings*>(nullptr));
}
std::vector<std::string> sampler_names() {
  return sorted_names<SamplerKind>(static_cast<SamplerSettings*>(nullptr));
}

MatcherTraits matcher_traits(const std::string& name) {
  return traits_by_name(name, static_cast<MatcherSettings*>(nullptr));
}

std::unique_ptr<Matcher> make_matcher(const MatcherSpec& spec) {
  return std::visit([](const auto& s) { return MatcherKind<std::decay_t<decltype(s)>>::make(s); },
                    spec.settings);
}

std::unique_ptr<Sampler> make_sampler(const SamplerSpec& spec) {
  return std::visit([](const auto& s) { return SamplerKind<std::decay_t<decltype(s)>>::make(s); },
                    spec.settings);
}

MatcherSpec with_wide_basin(const MatcherSpec& spec) {
  MatcherSpec wide = spec;
  if (MlndtSettings* s = wide.get<MlndtSettings>()) *s = wide_basin_on(*s);
  if (FbmlndtSettings* s = wide.get<FbmlndtSettings>()) s->mlndt = wide_basin_on(s->mlndt);
  return wide;
}

bool set_start_layer(MatcherSpec& spec, int layer) {
  if (MlndtSettings* s = spec.get<MlndtSettings>()) return s->start_layer = layer, true;
  if (FbmlndtSettings* s = spec.get<FbmlndtSettings>()) return s->mlndt.start_layer = layer, true;
  return false;
}

int last_layer(const MatcherSpec& spec) {
  if (const MlndtSettings* s = spec.get<MlndtSettings>()) return s->pyramid.layers;
  if (const FbmlndtSettings* s = spec.get<FbmlndtSettings>()) return s->mlndt.pyramid.layers;
  return 0;
}

}  // namespace sextant
