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
#include "sextant/matchers/matcher_choice.hpp"
#include "sextant/matchers/mlndt_presets.hpp"
#include "sextant/matchers/register_pair.hpp"
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
  // The README's C++ example: a matcher chosen by value, registered as `sextant match` does (no guess:
  // the wide basin searches). A corner of ground and two walls, ±2 cm rough, the input 0.3 m and 3° away.
  sextant::PointCloud reference;
  int k = 0;
  const auto rough = [&k] { return 0.02f * static_cast<float>(std::sin(12.9898 * ++k)); };
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j) {
      const float u = 0.25f * static_cast<float>(i), v = 0.25f * static_cast<float>(j);
      reference.push_back({u, v, rough()});
      if (j < 20) reference.push_back({u, rough(), 0.25f * static_cast<float>(j)});
      if (i < 20) reference.push_back({rough(), v, 0.25f * static_cast<float>(i)});
    }
  const Eigen::Isometry3d truth = sextant::to_isometry({0.3, -0.2, 0.0, 0.0, 0.0, 3.0 * M_PI / 180.0});
  const sextant::PointCloud input = reference.transformed(truth.inverse());
  sextant::PairRegistrationRequest request;
  request.matcher = sextant::matcher_choice(*sextant::mlndt_preset("default"));
  request.sampler = sextant::sampler_factory(sextant::GridSamplerSettings{});
  const sextant::PairRegistration r = sextant::register_pair(reference, input, request);
  check((r.match.result.T.translation() - truth.translation()).norm() < 0.05 &&
            r.match.result.quality.trusted(),
        "matchers: register_pair recovers the pose, trusted (" + r.search + ")");
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
