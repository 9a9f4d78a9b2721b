#pragma once
// A filter chosen by value: the settings struct, whose type names the filter. Parsed once at the
// edge (YAML: read_filter_spec of filters/yaml.hpp) and carried as this type from there:
//
//   FilterSpec spec = UkfSettings{};                   // the UKF, α = 1, β = 2, κ = 0
//   std::unique_ptr<Filter> f = make_filter(spec, model);
//
// The catalogue below is the one list of filters: a new filter is an alternative of FilterSettings and
// its FilterKind row (name, how it is built).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "sextant/filters/eseif.hpp"
#include "sextant/filters/fastslam.hpp"
#include "sextant/filters/filter.hpp"
#include "sextant/filters/gaussian_filters.hpp"
#include "sextant/filters/seif.hpp"
#include "sextant/filters/sigma_points.hpp"

namespace sextant {

/// The extended Kalman filter, eqs. (4.62)–(4.68).
struct EkfSettings {
  GaussianFilterSettings gaussian;
  bool valid(std::string* why) const { return gaussian.valid(why); }
};
/// The unscented Kalman filter, Tables 4.2–4.3.
struct UkfSettings {
  GaussianFilterSettings gaussian;
  UnscentedSettings unscented;
  bool valid(std::string* why) const { return gaussian.valid(why) && unscented.valid(why); }
};
/// The cubature Kalman filter, eqs. (4.69)–(4.81).
struct CkfSettings {
  GaussianFilterSettings gaussian;
  bool valid(std::string* why) const { return gaussian.valid(why); }
};
/// The randomised sigma-point Kalman filter, the stochastic integration rule of Table 4.4.
struct RspkfSettings {
  GaussianFilterSettings gaussian;
  StochasticIntegrationSettings integration;
  std::optional<std::uint64_t> seed;  ///< of its random sigma points; none: 1 (a run may give its own)
  bool valid(std::string* why) const { return gaussian.valid(why) && integration.valid(why); }
};
/// The extended information filter: SEIF without sparsification, with exact mean recovery.
struct EifSettings {
  bool valid(std::string* /*why*/) const { return true; }
};
/// FastSLAM 2.0 (Montemerlo et al. 2003).
struct FastSlam2Settings {
  FastSlamSettings particles;
  std::optional<std::uint64_t> seed;  ///< of its particles' draws; none: 1
  bool valid(std::string* why) const { return particles.valid(why); }
};

/// What the code knows of each filter: its name and how it is built on a model.
template <class Settings>
struct FilterKind;

template <>
struct FilterKind<EkfSettings> {
  static constexpr const char* kName = "ekf";
  static std::unique_ptr<Filter> make(const EkfSettings& s, std::shared_ptr<const SlamModel> m) {
    return std::make_unique<Ekf>(std::move(m), s.gaussian);
  }
};
template <>
struct FilterKind<UkfSettings> {
  static constexpr const char* kName = "ukf";
  static std::unique_ptr<Filter> make(const UkfSettings& s, std::shared_ptr<const SlamModel> m) {
    return std::make_unique<SigmaPointFilter>("ukf", std::move(m), make_unscented_rule(s.unscented),
                                              s.gaussian);
  }
};
template <>
struct FilterKind<CkfSettings> {
  static constexpr const char* kName = "ckf";
  static std::unique_ptr<Filter> make(const CkfSettings& s, std::shared_ptr<const SlamModel> m) {
    return std::make_unique<SigmaPointFilter>("ckf", std::move(m), make_cubature_rule(), s.gaussian);
  }
};
template <>
struct FilterKind<RspkfSettings> {
  static constexpr const char* kName = "rspkf";
  static std::unique_ptr<Filter> make(const RspkfSettings& s, std::shared_ptr<const SlamModel> m) {
    return std::make_unique<SigmaPointFilter>("rspkf", std::move(m),
                                              make_stochastic_integration_rule(s.integration), s.gaussian,
                                              s.seed.value_or(1));
  }
};
template <>
struct FilterKind<SeifSettings> {
  static constexpr const char* kName = "seif";  ///< the sparse extended information filter (§4.2.4)
  static std::unique_ptr<Filter> make(const SeifSettings& s, std::shared_ptr<const SlamModel> m) {
    return std::make_unique<Seif>("seif", std::move(m), s);
  }
};
template <>
struct FilterKind<EifSettings> {
  static constexpr const char* kName = "eif";
  static std::unique_ptr<Filter> make(const EifSettings&, std::shared_ptr<const SlamModel> m) {
    SeifSettings s;
    s.max_active_landmarks = 0;
    s.mean_recovery = "exact";
    return std::make_unique<Seif>("eif", std::move(m), s);
  }
};
template <>
struct FilterKind<EseifSettings> {
  static constexpr const char* kName = "eseif";  ///< exactly sparse EIF (Walter, Eustice, Leonard 2007)
  static std::unique_ptr<Filter> make(const EseifSettings& s, std::shared_ptr<const SlamModel> m) {
    return std::make_unique<Eseif>("eseif", std::move(m), s);
  }
};
template <>
struct FilterKind<FastSlam2Settings> {
  static constexpr const char* kName = "fastslam2";
  static std::unique_ptr<Filter> make(const FastSlam2Settings& s, std::shared_ptr<const SlamModel> m) {
    return std::make_unique<FastSlam>(std::move(m), s.particles, s.seed.value_or(1));
  }
};

using FilterSettings = std::variant<EkfSettings, UkfSettings, CkfSettings, RspkfSettings, SeifSettings,
                                    EifSettings, EseifSettings, FastSlam2Settings>;

/// A filter by value: one of the catalogue's settings structs.
struct FilterSpec {
  FilterSettings settings;  ///< default: the EKF

  FilterSpec() = default;
  template <class S, class = std::enable_if_t<std::is_constructible_v<FilterSettings, S>>>
  FilterSpec(S s) : settings(std::move(s)) {}  // NOLINT: a settings struct is a spec

  std::string name() const;
  bool valid(std::string* why) const;
  /// The settings when they are of type S, else null.
  template <class S>
  const S* get() const {
    return std::get_if<S>(&settings);
  }
  template <class S>
  S* get() {
    return std::get_if<S>(&settings);
  }
};

/// The catalogue's names, sorted (the spelling of YAML's `filter:`).
std::vector<std::string> filter_names();
/// The filter `name` with its defaults; none for an unknown name.
std::optional<FilterSpec> default_filter_spec(const std::string& name);

/// The filter as specified on `model`; std::invalid_argument when the settings are not valid (or do not
/// fit the model: an ESEIF relocation prior needs one σ per pose entry).
std::unique_ptr<Filter> make_filter(const FilterSpec& spec, std::shared_ptr<const SlamModel> model);
/// make_filter of `spec`, as a factory (checked now).
FilterFactory filter_factory(const FilterSpec& spec);

}  // namespace sextant
