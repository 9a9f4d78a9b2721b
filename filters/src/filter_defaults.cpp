// The built-in filters by name with their default settings (filter.hpp).
#include <cstdint>

#include "sextant/filters/eseif.hpp"
#include "sextant/filters/fastslam.hpp"
#include "sextant/filters/filter.hpp"
#include "sextant/filters/gaussian_filters.hpp"
#include "sextant/filters/seif.hpp"

namespace sextant {

FilterFactory default_filter(const std::string& name) {
  using Model = std::shared_ptr<const SlamModel>;
  const GaussianFilterSettings g;
  if (name == "ekf")
    return [g](Model m) -> std::unique_ptr<Filter> { return std::make_unique<Ekf>(std::move(m), g); };
  if (name == "ukf")
    return [g](Model m) -> std::unique_ptr<Filter> {
      return std::make_unique<SigmaPointFilter>("ukf", std::move(m), make_unscented_rule(UnscentedSettings{}),
                                                g);
    };
  if (name == "ckf")
    return [g](Model m) -> std::unique_ptr<Filter> {
      return std::make_unique<SigmaPointFilter>("ckf", std::move(m), make_cubature_rule(), g);
    };
  if (name == "rspkf")
    return [g](Model m) -> std::unique_ptr<Filter> {
      const std::uint64_t seed = 1;
      return std::make_unique<SigmaPointFilter>(
          "rspkf", std::move(m), make_stochastic_integration_rule(StochasticIntegrationSettings{}), g, seed);
    };
  if (name == "seif")
    return [](Model m) -> std::unique_ptr<Filter> {
      return std::make_unique<Seif>("seif", std::move(m), SeifSettings{});
    };
  if (name == "eseif")
    return [](Model m) -> std::unique_ptr<Filter> {
      return std::make_unique<Eseif>("eseif", std::move(m), EseifSettings{});
    };
  if (name == "fastslam2")
    return [](Model m) -> std::unique_ptr<Filter> { return std::make_unique<FastSlam>(std::move(m)); };
  if (name == "eif")
    return [](Model m) -> std::unique_ptr<Filter> {
      SeifSettings s;  // SEIF without sparsification, exact mean recovery
      s.max_active_landmarks = 0;
      s.mean_recovery = "exact";
      return std::make_unique<Seif>("eif", std::move(m), s);
    };
  return {};
}

}  // namespace sextant
