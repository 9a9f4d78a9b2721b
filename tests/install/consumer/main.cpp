// Uses every installed Sextant library once (so that each is linked and loaded, not dropped by
// --as-needed) and checks the answers; exit 0 on success. Run from a moved prefix, it proves the
// install is relocatable.
#include <cmath>
#include <iostream>
#include <string>

#include "sextant/core/pose.hpp"
#include "sextant/eval/statistics.hpp"
#include "sextant/experiments/provenance.hpp"
#include "sextant/features/extraction.hpp"
#include "sextant/filters/plane_slam.hpp"
#include "sextant/matchers/icp.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/posegraph/pose_graph.hpp"
#include "sextant/synth/settings.hpp"

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
  check(sextant::parse_odometry_map("local_map") == sextant::OdometryMap::local_map, "odometry: map name");
  check(sextant::PlaneSlamSettings{}.valid(&why), "filters: default plane-SLAM settings");
  bool known = false;
  sextant::robust_loss_from_string("huber", &known);
  check(known, "posegraph: robust loss name");
  check(sextant::synth::WorldSettings{}.valid(&why), "synth: default world");
  check(!sextant::sextant_version().empty(), "experiments: version " + sextant::sextant_version());
  return failures == 0 ? 0 : 1;
}
