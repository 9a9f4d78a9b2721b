#include <memory>

#include "sextant/experiments/run_kind.hpp"

// The built-in run kinds. Kind `x` is the folder src/kinds/x/ (compiled by its presence: the CMake
// source list globs src/kinds/), whose kind.cpp defines make_x_kind(). Adding a family is that
// folder and one line here: its name and what it runs (keep sorted).
#define SEXTANT_RUN_KINDS(KIND)                                                                          \
  KIND(metric_examples, "the Wulf and Kümmerle metrics on the thesis' worked examples")                  \
  KIND(place_recognition, "loop-closure candidates by proximity or Scan Context under inflated drift")   \
  KIND(plane_features, "plane merging tests, extraction and semantic association")                       \
  KIND(plane_slam, "plane SLAM over a campus scan sequence, any filter")                                 \
  KIND(pose_graph, "chained scan matching, a pose graph with loop closures, and the plane-SLAM filters") \
  KIND(registration, "scan pairs with an initial guess, any matcher × sampler")                          \
  KIND(selftest, "runner self-test: sleeps and records seeds (sharding, resume, merge)")                 \
  KIND(sequence, "a matcher over a sequence of scans, chained or fused with odometry by a KF")           \
  KIND(simulation, "2D room with ML-NDT into the EKF, range-bearing Monte Carlo of filters")

namespace sextant {

#define SEXTANT_DECLARE_KIND(name, what) std::unique_ptr<RunKind> make_##name##_kind();
SEXTANT_RUN_KINDS(SEXTANT_DECLARE_KIND)
#undef SEXTANT_DECLARE_KIND

const RunKindRegistry& run_kind_registry() {
  static const RunKindRegistry registry = [] {
    RunKindRegistry r("run kind");
#define SEXTANT_ADD_KIND(name, what) r.add(#name, what, [] { return make_##name##_kind(); });
    SEXTANT_RUN_KINDS(SEXTANT_ADD_KIND)
#undef SEXTANT_ADD_KIND
    return r;
  }();
  return registry;
}

}  // namespace sextant
