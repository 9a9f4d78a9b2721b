#include "kit/registration_method.hpp"

#include "sextant/core/settings_reader.hpp"
#include "sextant/matchers/feature_based_sampler.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/sampler.hpp"

namespace sextant {

RegistrationMethod read_registration_method(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  RegistrationMethod m;
  in.require("name", m.name);
  in.require("matcher", m.matcher);
  m.settings = in.child("settings");
  in.read("sampler", m.sampler);
  m.sampler_settings = in.child("sampler_settings");
  if (declares_adaptive_start(node)) {
    m.adaptive = true;
    m.adaptive_start = read_adaptive_start(in.child("adaptive_start"), file);
  }
  in.finish();
  if (!matcher_registry().contains(m.matcher)) {
    std::string names;
    for (const auto& n : matcher_registry().names()) names += (names.empty() ? "" : ", ") + n;
    in.fail("matcher", "key 'matcher': unknown matcher '" + m.matcher + "' (known: " + names + ")");
  }
  if (!sampler_registry().contains(m.sampler)) {
    std::string names;
    for (const auto& n : sampler_registry().names()) names += (names.empty() ? "" : ", ") + n;
    in.fail("sampler", "key 'sampler': unknown sampler '" + m.sampler + "' (known: " + names + ")");
  }
  // Building them checks the settings (InputError with the settings' own lines).
  (void)make_matcher(m.matcher, m.settings, file);
  (void)make_sampler(m.sampler, m.sampler_settings, file);
  if (m.adaptive) {
    if (m.matcher == "mlndt")
      m.last_layer = read_mlndt_settings(m.settings, file).pyramid.layers;
    else if (m.matcher == "fbmlndt")
      m.last_layer = read_fbmlndt_settings(m.settings, file).mlndt.pyramid.layers;
    else
      in.fail("adaptive_start",
              "key 'adaptive_start': needs a matcher with a layer pyramid (mlndt or fbmlndt)");
    if (m.adaptive_start.middle_layer > m.last_layer)
      in.fail("adaptive_start",
              "key 'adaptive_start': middle_layer is past the last layer " + std::to_string(m.last_layer));
  }
  return m;
}

}  // namespace sextant
