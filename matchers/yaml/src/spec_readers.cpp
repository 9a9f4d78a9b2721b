// The matcher and sampler specs from YAML by name (matchers/yaml.hpp): one reader per alternative of
// the catalogue (matcher_spec.hpp).
#include "readers.hpp"

#include "sextant/features/yaml.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant {

namespace {

void read_into(const YAML::Node& n, const std::string& f, MlndtSettings* s) {
  *s = read_mlndt_settings(n, f);
}
void read_into(const YAML::Node& n, const std::string& f, FbmlndtSettings* s) {
  *s = read_fbmlndt_settings(n, f);
}
void read_into(const YAML::Node& n, const std::string& f, NdtSettings* s) {
  *s = read_ndt_settings(n, f);
}
void read_into(const YAML::Node& n, const std::string& f, IcpP2pSettings* s) {
  *s = IcpP2pSettings{read_icp_settings(IcpObjective::kPointToPoint, n, f)};
}
void read_into(const YAML::Node& n, const std::string& f, IcpP2lSettings* s) {
  *s = IcpP2lSettings{read_icp_settings(IcpObjective::kPointToPlane, n, f)};
}
void read_into(const YAML::Node& n, const std::string& f, PclNdtSettings* s) {
  *s = read_pcl_ndt_settings(n, f);
}
void read_into(const YAML::Node& n, const std::string& f, PclIcpSettings* s) {
  *s = read_pcl_icp_settings(n, f);
}
void read_into(const YAML::Node& n, const std::string& f, PclGicpSettings* s) {
  *s = read_pcl_gicp_settings(n, f);
}

template <class Settings>
Settings checked(SettingsReader& in, const Settings& s) {
  in.finish();
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
  return s;
}

void read_into(const YAML::Node& n, const std::string& f, AllPointsSettings* s) {
  SettingsReader in(n, f);
  *s = checked(in, AllPointsSettings{});
}
void read_into(const YAML::Node& n, const std::string& f, GridSamplerSettings* s) {
  *s = read_grid_sampler_settings(n, f);
}
void read_into(const YAML::Node& n, const std::string& f, PlaneExtractionSettings* s) {
  *s = read_plane_extraction_settings(n, f);
}
void read_into(const YAML::Node& n, const std::string& f, RandomSamplerSettings* s) {
  SettingsReader in(n, f);
  in.read("fraction", s->fraction);
  *s = checked(in, *s);
}
void read_into(const YAML::Node& n, const std::string& f, RegularSamplerSettings* s) {
  SettingsReader in(n, f);
  in.read("step", s->step);
  *s = checked(in, *s);
}

/// Reads the alternative whose kind is named `name` into `out`; false when none is.
template <template <class> class Kind, class... Settings>
bool read_named(const std::string& name, const YAML::Node& node, const std::string& file,
                std::variant<Settings...>* out) {
  const auto read_if = [&](auto* as) {
    using S = std::remove_pointer_t<decltype(as)>;
    if (name != Kind<S>::kName) return false;
    S settings;
    read_into(node, file, &settings);
    *out = std::move(settings);
    return true;
  };
  return (read_if(static_cast<Settings*>(nullptr)) || ...);
}

std::string unknown(const std::string& what, const std::string& name, const std::vector<std::string>& known) {
  std::string message = "unknown " + what + " '" + name + "' (known:";
  for (const std::string& k : known) message += " " + k;
  return message + ")";
}

}  // namespace

MatcherSpec read_matcher_spec(const std::string& name, const YAML::Node& settings, const std::string& file) {
  MatcherSpec spec;
  if (!read_named<MatcherKind>(name, settings, file, &spec.settings))
    throw InputError(file, "", unknown("matcher", name, matcher_names()));
  return spec;
}

SamplerSpec read_sampler_spec(const std::string& name, const YAML::Node& settings, const std::string& file) {
  SamplerSpec spec;
  if (!read_named<SamplerKind>(name, settings, file, &spec.settings))
    throw InputError(file, "", unknown("sampler", name, sampler_names()));
  return spec;
}

std::unique_ptr<Matcher> make_matcher(const std::string& name, const YAML::Node& settings,
                                      const std::string& file) {
  return make_matcher(read_matcher_spec(name, settings, file));
}

std::unique_ptr<Sampler> make_sampler(const std::string& name, const YAML::Node& settings,
                                      const std::string& file) {
  return make_sampler(read_sampler_spec(name, settings, file));
}

}  // namespace sextant
