#include <cstdint>

#include "sextant/core/settings_reader.hpp"
#include "sextant/filters/eseif.hpp"
#include "sextant/filters/fastslam.hpp"
#include "sextant/filters/gaussian_filters.hpp"
#include "sextant/filters/seif.hpp"
#include "sextant/filters/yaml.hpp"

namespace sextant {
namespace {

template <class Settings>
void check(const SettingsReader& in, const Settings& s) {
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
}

GaussianFilterSettings read_gaussian(SettingsReader& in) {
  GaussianFilterSettings s;
  in.read("joseph_form", s.joseph_form);
  in.read("symmetrize", s.symmetrize);
  in.read("check_covariance", s.check_covariance);
  check(in, s);
  return s;
}

std::uint64_t read_seed(SettingsReader& in) {
  long long seed = 1;
  in.read("seed", seed);
  if (seed < 0) in.fail("seed", "seed must be >= 0");
  return static_cast<std::uint64_t>(seed);
}

void fill(FilterRegistry& r) {
  r.add("ekf", "extended Kalman filter, eqs. (4.62)-(4.68)",
        [](std::shared_ptr<const SlamModel> model, const YAML::Node& node, const std::string& file) {
          SettingsReader in(node, file);
          const auto s = read_gaussian(in);
          in.finish();
          return std::make_unique<Ekf>(std::move(model), s);
        });
  r.add("ukf", "unscented Kalman filter, Tables 4.2-4.3 (alpha, beta, kappa)",
        [](std::shared_ptr<const SlamModel> model, const YAML::Node& node, const std::string& file) {
          SettingsReader in(node, file);
          const auto s = read_gaussian(in);
          UnscentedSettings u;
          in.read("alpha", u.alpha);
          in.read("beta", u.beta);
          in.read("kappa", u.kappa);
          in.read("kappa_three_minus_n", u.kappa_three_minus_n);
          check(in, u);
          in.finish();
          return std::make_unique<SigmaPointFilter>("ukf", std::move(model), make_unscented_rule(u), s);
        });
  r.add("ckf", "cubature Kalman filter, eqs. (4.69)-(4.81)",
        [](std::shared_ptr<const SlamModel> model, const YAML::Node& node, const std::string& file) {
          SettingsReader in(node, file);
          const auto s = read_gaussian(in);
          in.finish();
          return std::make_unique<SigmaPointFilter>("ckf", std::move(model), make_cubature_rule(), s);
        });
  r.add("rspkf", "randomized sigma-point Kalman filter, stochastic integration rule (Table 4.4)",
        [](std::shared_ptr<const SlamModel> model, const YAML::Node& node, const std::string& file) {
          SettingsReader in(node, file);
          const auto s = read_gaussian(in);
          StochasticIntegrationSettings si;
          in.read("iterations", si.iterations);
          check(in, si);
          const std::uint64_t seed = read_seed(in);
          in.finish();
          return std::make_unique<SigmaPointFilter>("rspkf", std::move(model),
                                                    make_stochastic_integration_rule(si), s, seed);
        });
  r.add("seif", "sparse extended information filter (section 4.2.4)",
        [](std::shared_ptr<const SlamModel> model, const YAML::Node& node, const std::string& file) {
          SettingsReader in(node, file);
          SeifSettings s;
          in.read("max_active_landmarks", s.max_active_landmarks);
          in.read("mean_recovery", s.mean_recovery);
          in.read("relaxation_iterations", s.relaxation_iterations);
          check(in, s);
          in.finish();
          return std::make_unique<Seif>("seif", std::move(model), s);
        });
  r.add("eseif", "exactly sparse extended information filter (Walter, Eustice, Leonard 2007): relocalization",
        [](std::shared_ptr<const SlamModel> model, const YAML::Node& node, const std::string& file) {
          SettingsReader in(node, file);
          EseifSettings s;
          in.read("max_active_landmarks", s.max_active_landmarks);
          in.read("relocation_landmarks", s.relocation_landmarks);
          in.read("relocation_prior", s.relocation_prior);
          in.read("mean_recovery", s.mean_recovery);
          check(in, s);
          if (!s.relocation_prior.empty() && static_cast<int>(s.relocation_prior.size()) != model->pose_dim())
            in.fail("relocation_prior", "relocation_prior needs one sigma per pose entry (" +
                                            std::to_string(model->pose_dim()) + ")");
          in.finish();
          return std::make_unique<Eseif>("eseif", std::move(model), s);
        });
  r.add("fastslam2", "FastSLAM 2.0 (Montemerlo et al. 2003): particles with per-landmark EKFs, shared map",
        [](std::shared_ptr<const SlamModel> model, const YAML::Node& node, const std::string& file) {
          SettingsReader in(node, file);
          FastSlamSettings s;
          in.read("particles", s.particles);
          in.read("resample_threshold", s.resample_threshold);
          check(in, s);
          const std::uint64_t seed = read_seed(in);
          in.finish();
          return std::make_unique<FastSlam>(std::move(model), s, seed);
        });
  r.add("eif", "extended information filter: SEIF without sparsification, exact mean recovery",
        [](std::shared_ptr<const SlamModel> model, const YAML::Node& node, const std::string& file) {
          SettingsReader in(node, file);
          in.finish();
          SeifSettings s;
          s.max_active_landmarks = 0;
          s.mean_recovery = "exact";
          return std::make_unique<Seif>("eif", std::move(model), s);
        });
}

}  // namespace

FilterRegistry& filter_registry() {
  static FilterRegistry registry = [] {
    FilterRegistry r("filter");
    fill(r);
    return r;
  }();
  return registry;
}

std::unique_ptr<Filter> make_filter(const std::string& name, std::shared_ptr<const SlamModel> model,
                                    const YAML::Node& settings, const std::string& file) {
  return filter_registry().create(name, std::move(model), settings, file);
}

}  // namespace sextant
