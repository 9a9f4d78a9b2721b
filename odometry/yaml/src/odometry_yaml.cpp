// The odometry's matcher and sampler from YAML (Sextant::odometry_yaml).
#include "sextant/odometry/yaml.hpp"

namespace sextant {

OdometryRegistration odometry_registration(const OdometryMethod& method) {
  OdometryRegistration r;
  r.matcher = method.matcher.empty() ? MatcherChoice{}
                                     : matcher_choice(method.matcher, method.settings, "<odometry matcher>",
                                                      "<odometry matcher, recovery>");
  r.sampler = method.sampler.empty()
                  ? SamplerFactory{}
                  : sampler_factory(method.sampler, method.sampler_settings, "<odometry sampler>");
  return r;
}

}  // namespace sextant
