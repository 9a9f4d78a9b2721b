// Uses every installed Sextant library once (so that each is linked and loaded, not dropped by
// --as-needed) and checks the answers; exit 0 on success. Run from a moved prefix, it proves the
// install is relocatable.
#include <cmath>
#include <iostream>
#include <string>

#include "sextant/core/pose.hpp"
#include "sextant/core/yaml.hpp"
#include "sextant/eval/statistics.hpp"
#include "sextant/eval/yaml.hpp"
#include "sextant/features/extraction.hpp"
#include "sextant/features/yaml.hpp"
#include "sextant/filters/plane_slam.hpp"
#include "sextant/filters/yaml.hpp"
#include "sextant/matchers/icp.hpp"
#include "sextant/matchers/yaml.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/pipeline/provenance.hpp"
#include "sextant/posegraph/pose_graph.hpp"
#include "sextant/posegraph/yaml.hpp"
#include "sextant/synth/settings.hpp"
#include "sextant/synth/yaml.hpp"

int main() {
  int failures = 0;
  const auto check = [&](bool ok, const std::string& what) {
    std::cout << what << (ok ? " ok" : " WRONG") << "\n";
    failures += ok ? 0 : 1;
  };
  // core: a turns 90° left, so b's 2 m forward becomes 2 m along y: (1, 2, 0), yaw 90°.
  const Eigen::Isometry3d a = sextant::to_isometry({1.0, 0.0, 0.0, 0.0, 0.0, M_PI / 2});
  const Eigen::Isometry3d b = sextant::to_isometry({2.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  const sextant::Pose6 c = sextant::to_pose6(sextant::compose(a, b));
  check(std::abs(c.x - 1.0) < 1e-12 && std::abs(c.y - 2.0) < 1e-12 && std::abs(c.gamma - M_PI / 2) < 1e-12,
        "core: composed pose");
  check(sextant::summarize({1.0, 2.0, 3.0}).median == 2.0, "eval: median");
  std::string why;
  check(sextant::PlaneExtractionSettings{}.valid(&why), "features: default extraction settings");
  check(sextant::IcpSettings{}.valid(&why), "matchers: default ICP settings");
  check(
      sextant::parse_enum(sextant::kOdometryMapNames, "local_map", "map") == sextant::OdometryMap::local_map,
      "odometry: map name");
  check(sextant::PlaneSlamSettings{}.valid(&why), "filters: default plane-SLAM settings");
  sextant::RobustLoss loss{};
  check(sextant::from_string("huber", &loss) && loss == sextant::RobustLoss::huber,
        "posegraph: robust loss name");
  check(sextant::synth::WorldSettings{}.valid(&why), "synth: default world");
  check(!sextant::sextant_version().empty(), "pipeline: version " + sextant::sextant_version());
  // The YAML targets: one reader of each.
  const YAML::Node node = YAML::Load("{layers: 3}");
  check(sextant::read_mlndt_settings(node, "consumer").pyramid.layers == 3, "matchers_yaml: layers");
  check(sextant::read_plane_extraction_settings(YAML::Load("{cell_size: 3}"), "c").cell_size == 3.0,
        "features_yaml: cell size");
  check(sextant::read_pose_graph_settings(YAML::Node(), "c").max_iterations > 0, "posegraph_yaml: defaults");
  check(sextant::read_plane_slam_settings(YAML::Load("{filter: ukf}"), "c").filter == "ukf",
        "filters_yaml: filter");
  check(sextant::read_rpe_settings(YAML::Node(), "c").delta > 0, "eval_yaml: defaults");
  check(sextant::synth::read_campus_settings(YAML::Node(), "c").world.valid(&why), "synth_yaml: defaults");
  check(sextant::read_matcher_spec("icp_p2l", YAML::Node(), "c").name() == "icp_p2l", "matchers_yaml: spec");
  check(sextant::yaml_line(YAML::Node()) == 0, "core_yaml: line of a null node");
  return failures == 0 ? 0 : 1;
}
