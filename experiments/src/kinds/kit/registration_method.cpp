#include "kit/registration_method.hpp"

#include <algorithm>

#include "sextant/core/settings_reader.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant {

RegistrationMethod read_registration_method(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  RegistrationMethod m;
  std::string matcher, sampler = "all";
  in.require("name", m.name);
  in.require("matcher", matcher);
  const YAML::Node settings = in.child("settings");
  in.read("sampler", sampler);
  const YAML::Node sampler_settings = in.child("sampler_settings");
  if (declares_adaptive_start(node)) {
    m.adaptive = true;
    m.adaptive_start = read_adaptive_start(in.child("adaptive_start"), file);
  }
  in.finish();
  const auto unknown = [&](const char* key, const std::string& name, const std::vector<std::string>& known) {
    std::string names;
    for (const auto& n : known) names += (names.empty() ? "" : ", ") + n;
    in.fail(key, std::string("key '") + key + "': unknown " + key + " '" + name + "' (known: " + names + ")");
  };
  const std::vector<std::string> matchers = matcher_names(), samplers = sampler_names();
  if (std::find(matchers.begin(), matchers.end(), matcher) == matchers.end())
    unknown("matcher", matcher, matchers);
  if (std::find(samplers.begin(), samplers.end(), sampler) == samplers.end())
    unknown("sampler", sampler, samplers);
  m.matcher = read_matcher_spec(matcher, settings, file);
  m.sampler = read_sampler_spec(sampler, sampler_settings, file);
  if (m.adaptive) {
    if (!m.matcher.traits().layer_pyramid)
      in.fail("adaptive_start",
              "key 'adaptive_start': needs a matcher with a layer pyramid (mlndt or fbmlndt)");
    if (m.adaptive_start.middle_layer > last_layer(m.matcher))
      in.fail("adaptive_start", "key 'adaptive_start': middle_layer is past the last layer " +
                                    std::to_string(last_layer(m.matcher)));
  }
  return m;
}

}  // namespace sextant
