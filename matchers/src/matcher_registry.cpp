// The matcher registry: one line per built-in matcher (others insert their own lines).
#include "sextant/matchers/feature_based_sampler.hpp"
#include "sextant/matchers/icp.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/ndt_matcher.hpp"
#include "sextant/matchers/pcl_peers.hpp"

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

}  // namespace sextant
