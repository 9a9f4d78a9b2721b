// The catalogue of filters by value (filter_spec.hpp).
#include "sextant/filters/filter_spec.hpp"

#include <algorithm>
#include <stdexcept>

namespace sextant {

namespace {

template <class... Settings>
std::vector<std::string> sorted_names(const std::variant<Settings...>*) {
  std::vector<std::string> names{FilterKind<Settings>::kName...};
  std::sort(names.begin(), names.end());
  return names;
}

template <class... Settings>
std::optional<FilterSpec> defaults_named(const std::string& name, const std::variant<Settings...>*) {
  std::optional<FilterSpec> spec;
  ((name == FilterKind<Settings>::kName ? void(spec = FilterSpec(Settings{})) : void()), ...);
  return spec;
}

}  // namespace

std::string FilterSpec::name() const {
  return std::visit([](const auto& s) -> std::string { return FilterKind<std::decay_t<decltype(s)>>::kName; },
                    settings);
}

bool FilterSpec::valid(std::string* why) const {
  return std::visit([why](const auto& s) { return s.valid(why); }, settings);
}

std::vector<std::string> filter_names() {
  return sorted_names(static_cast<FilterSettings*>(nullptr));
}

std::optional<FilterSpec> default_filter_spec(const std::string& name) {
  return defaults_named(name, static_cast<FilterSettings*>(nullptr));
}

std::unique_ptr<Filter> make_filter(const FilterSpec& spec, std::shared_ptr<const SlamModel> model) {
  std::string why;
  if (!spec.valid(&why)) throw std::invalid_argument("invalid " + spec.name() + " settings: " + why);
  return std::visit(
      [&model](const auto& s) { return FilterKind<std::decay_t<decltype(s)>>::make(s, std::move(model)); },
      spec.settings);
}

FilterFactory filter_factory(const FilterSpec& spec) {
  std::string why;
  if (!spec.valid(&why)) throw std::invalid_argument("invalid " + spec.name() + " settings: " + why);
  return [spec](std::shared_ptr<const SlamModel> model) { return make_filter(spec, std::move(model)); };
}

FilterFactory default_filter(const std::string& name) {
  const std::optional<FilterSpec> spec = default_filter_spec(name);
  return spec ? filter_factory(*spec) : FilterFactory{};
}

}  // namespace sextant
