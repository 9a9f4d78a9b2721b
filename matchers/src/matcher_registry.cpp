// The matcher registry: one line per built-in matcher (others insert their own lines).
#include "sextant/matchers/icp.hpp"
#include "sextant/matchers/matcher.hpp"

namespace sextant {

namespace {

MatcherRegistry make_builtin_matchers() {
  MatcherRegistry registry("matcher");
  registry.add("icp_p2l", "point-to-plane ICP (PCA normals, k-d tree)", make_icp_p2l_matcher);
  registry.add("icp_p2p", "point-to-point ICP (closed-form SVD, k-d tree)", make_icp_p2p_matcher);
  return registry;
}

}  // namespace

MatcherRegistry& matcher_registry() {
  static MatcherRegistry registry = make_builtin_matchers();
  return registry;
}

std::unique_ptr<Matcher> make_matcher(const std::string& name, const YAML::Node& settings,
                                      const std::string& file) {
  return matcher_registry().create(name, settings, file);
}

}  // namespace sextant
