// The matcher registry: one line per built-in matcher (others insert their own lines).
#include "readers.hpp"

#include "sextant/matchers/judged_matcher.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant {

namespace {

MatcherRegistry make_builtin_matchers() {
  MatcherRegistry registry("matcher");
  registry.add("fbmlndt", "ML-NDT on the plane inliers of the input scan (FbML-NDT, Table 3.2)",
               create_fbmlndt_matcher);
  registry.add("icp_p2l", "point-to-plane ICP (PCA normals, k-d tree)", make_icp_p2l_matcher);
  registry.add("icp_p2p", "point-to-point ICP (closed-form SVD, k-d tree)", make_icp_p2p_matcher);
  registry.add("pcl_gicp", "PCL GeneralizedIterativeClosestPoint (peer)", make_pcl_gicp_matcher);
  registry.add("pcl_icp", "PCL IterativeClosestPoint (peer)", make_pcl_icp_matcher);
  registry.add("pcl_ndt", "PCL NormalDistributionsTransform (peer)", make_pcl_ndt_matcher);
  registry.add("mlndt", "Multi-Layered NDT, Mahalanobis score (Table 3.1)", create_mlndt_matcher);
  registry.add("ndt", "classic P2D-NDT, Gaussian score, fixed grid", create_ndt_matcher);
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

MatcherChoice matcher_choice(const std::string& name, const YAML::Node& settings, const std::string& file,
                             const std::string& wide_file) {
  MatcherChoice c;
  c.name = name;
  c.make = [name, settings, file] { return judged(make_matcher(name, settings, file)); };
  if (const std::optional<YAML::Node> wide = with_wide_basin(name, settings)) {
    const std::string where = wide_file.empty() ? file : wide_file;
    c.make_wide = [name, node = *wide, where] { return make_matcher(name, node, where); };
  }
  const YAML::Node& given = settings;
  c.own_wide_basin = given.IsMap() && given["wide_basin"].IsDefined();
  return c;
}

}  // namespace sextant
