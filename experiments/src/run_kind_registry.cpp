#include "sextant/experiments/run_kind.hpp"

#include "kinds/kinds.hpp"

namespace sextant {

const RunKindRegistry& run_kind_registry() {
  static const RunKindRegistry registry = [] {
    RunKindRegistry r("run kind");
    // One line per kind (keep sorted).
    r.add("metric_examples", "the Wulf and Kümmerle metrics on the thesis' worked examples",
          [] { return make_metric_examples_kind(); });
    r.add("plane_features", "plane merging tests, extraction and semantic association",
          [] { return make_plane_features_kind(); });
    r.add("plane_slam", "plane SLAM over a campus scan sequence, any filter",
          [] { return make_plane_slam_kind(); });
    r.add("pose_graph", "chained scan matching, a pose graph with loop closures, and the plane-SLAM filters",
          [] { return make_pose_graph_kind(); });
    r.add("place_recognition", "loop-closure candidates by proximity or Scan Context under inflated drift",
          [] { return make_place_recognition_kind(); });
    r.add("registration", "scan pairs with an initial guess, any matcher × sampler",
          [] { return make_registration_kind(); });
    r.add("sequence", "a matcher over a sequence of scans, chained or fused with odometry by a KF",
          [] { return make_sequence_kind(); });
    r.add("selftest", "runner self-test: sleeps and records seeds (sharding, resume, merge)",
          [] { return make_selftest_kind(); });
    r.add("simulation", "2D room with ML-NDT into the EKF, range-bearing Monte Carlo of filters",
          [] { return make_simulation_kind(); });
    return r;
  }();
  return registry;
}

}  // namespace sextant
