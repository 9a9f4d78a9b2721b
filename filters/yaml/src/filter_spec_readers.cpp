// The filter specs from YAML by name (filters/yaml.hpp): one reader per alternative of the catalogue
// (filter_spec.hpp).
#include <cstdint>

#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
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

std::optional<std::uint64_t> read_seed(SettingsReader& in) {
  if (!in.has("seed")) return std::nullopt;
  long long seed = 1;
  in.read("seed", seed);
  if (seed < 0) in.fail("seed", "seed must be >= 0");
  return static_cast<std::uint64_t>(seed);
}

void read_into(SettingsReader& in, int, EkfSettings* s) {
  s->gaussian = read_gaussian(in);
}
void read_into(SettingsReader& in, int, CkfSettings* s) {
  s->gaussian = read_gaussian(in);
}
void read_into(SettingsReader&, int, EifSettings*) {}
void read_into(SettingsReader& in, int, UkfSettings* s) {
  s->gaussian = read_gaussian(in);
  in.read("alpha", s->unscented.alpha);
  in.read("beta", s->unscented.beta);
  in.read("kappa", s->unscented.kappa);
  in.read("kappa_three_minus_n", s->unscented.kappa_three_minus_n);
  check(in, s->unscented);
}
void read_into(SettingsReader& in, int, RspkfSettings* s) {
  s->gaussian = read_gaussian(in);
  in.read("iterations", s->integration.iterations);
  check(in, s->integration);
  s->seed = read_seed(in);
}
void read_into(SettingsReader& in, int, SeifSettings* s) {
  in.read("max_active_landmarks", s->max_active_landmarks);
  in.read("mean_recovery", s->mean_recovery);
  in.read("relaxation_iterations", s->relaxation_iterations);
  check(in, *s);
}
void read_into(SettingsReader& in, int pose_dim, EseifSettings* s) {
  in.read("max_active_landmarks", s->max_active_landmarks);
  in.read("relocation_landmarks", s->relocation_landmarks);
  in.read("relocation_prior", s->relocation_prior);
  in.read("mean_recovery", s->mean_recovery);
  check(in, *s);
  if (pose_dim > 0 && !s->relocation_prior.empty() &&
      static_cast<int>(s->relocation_prior.size()) != pose_dim)
    in.fail("relocation_prior",
            "relocation_prior needs one sigma per pose entry (" + std::to_string(pose_dim) + ")");
}
void read_into(SettingsReader& in, int, FastSlam2Settings* s) {
  in.read("particles", s->particles.particles);
  in.read("resample_threshold", s->particles.resample_threshold);
  check(in, s->particles);
  s->seed = read_seed(in);
}

template <class... Settings>
bool read_named(const std::string& name, SettingsReader& in, int pose_dim, std::variant<Settings...>* out) {
  const auto read_if = [&](auto* as) {
    using S = std::remove_pointer_t<decltype(as)>;
    if (name != FilterKind<S>::kName) return false;
    S settings;
    read_into(in, pose_dim, &settings);
    *out = std::move(settings);
    return true;
  };
  return (read_if(static_cast<Settings*>(nullptr)) || ...);
}

}  // namespace

FilterSpec read_filter_spec(const std::string& name, const YAML::Node& settings, const std::string& file,
                            int pose_dim) {
  FilterSpec spec;
  SettingsReader in(settings, file);
  if (!read_named(name, in, pose_dim, &spec.settings)) {
    std::string known;
    for (const std::string& n : filter_names()) known += " " + n;
    throw InputError(file, "", "unknown filter '" + name + "' (known:" + known + ")");
  }
  in.finish();
  return spec;
}

std::unique_ptr<Filter> make_filter(const std::string& name, std::shared_ptr<const SlamModel> model,
                                    const YAML::Node& settings, const std::string& file) {
  const int pose_dim = model ? model->pose_dim() : 0;
  return make_filter(read_filter_spec(name, settings, file, pose_dim), std::move(model));
}

}  // namespace sextant
