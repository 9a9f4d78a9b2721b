// Loop closing over a drifted chain: the odometry graph, and closures from the proximity search and
// from place recognition, against a known trajectory.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "exact_registration.hpp"
#include "sextant/posegraph/loop_closing.hpp"
#include "sextant_test/worst_error.hpp"
#include "square_drive.hpp"

namespace sextant {
namespace {

using test::PoseList;

/// The chain of the truth's steps, each turned by `yaw_drift` [rad] more than it was.
PoseList drifted_chain(const PoseList& truth, double yaw_drift, std::vector<ChainStep>* steps) {
  PoseList chain{truth.front()};
  for (std::size_t k = 1; k < truth.size(); ++k) {
    ChainStep s;
    s.relative = relative(truth[k - 1], truth[k]) * test::planar_pose(0, 0, yaw_drift);
    s.hessian = Matrix6d::Identity() * 1e4;
    s.converged = true;
    steps->push_back(s);
    chain.push_back(chain.back() * s.relative);
  }
  return chain;
}

using test::exact_registration;

using test::worst_error;

/// The revisits Scan Context would propose: j = 80 + k onto k, every fourth k.
std::vector<PlaceMatch> true_places() {
  std::vector<PlaceMatch> places;
  for (std::size_t k = 2; k < 78; k += 4) places.push_back({k, k + 80, {0.05, 0, 0.0}});
  return places;
}

TEST(OdometryGraph, StepsWithoutAUsableHessianGetTheMedianInformation) {
  const PoseList truth = test::square_drive(2);
  std::vector<ChainStep> steps;
  const PoseList chain = drifted_chain(truth, 0.0, &steps);
  steps[3].converged = false;
  steps[7].hessian.setZero();
  steps[9].hessian *= 3.0;
  const OdometryGraph g = odometry_graph(chain, steps);
  EXPECT_EQ(g.graph.size(), chain.size());
  EXPECT_EQ(g.graph.edges().size(), steps.size());
  EXPECT_EQ(g.fallback_information, 2u);
  EXPECT_TRUE(g.graph.edges()[3].information.isApprox(g.typical_information));
  EXPECT_TRUE(g.graph.edges()[7].information.isApprox(g.typical_information));
  EXPECT_FALSE(g.graph.edges()[9].information.isApprox(g.typical_information));
}

TEST(LoopClosing, ProximityClosesASmallDriftAndPlacesCloseALargeOne) {
  const PoseList truth = test::square_drive(2);
  LoopClosingSettings s;
  s.closure.radius = 6.0;
  s.closure.min_index_gap = 40;
  s.closure.min_path_gap = 60.0;
  for (const double drift_deg : {0.02, 0.5}) {
    std::vector<ChainStep> steps;
    const PoseList chain = drifted_chain(truth, drift_deg * M_PI / 180.0, &steps);
    const PoseGraph graph = odometry_graph(chain, steps).graph;
    const bool small = drift_deg < 0.1;
    ASSERT_EQ(worst_error(chain, truth) < s.closure.radius, small) << drift_deg;  // the premise
    for (const LoopCandidateSource source : {LoopCandidateSource::proximity, LoopCandidateSource::both}) {
      s.source = source;
      Rng rng(3);
      const LoopClosingResult r = close_loops(graph, true_places(), exact_registration(truth), s, rng);
      const bool should_close = small || source == LoopCandidateSource::both;
      EXPECT_EQ(r.accepted() > 0, should_close) << drift_deg << "° " << to_string(source);
      if (should_close)
        EXPECT_LT(worst_error(r.poses, truth), 0.25 * worst_error(chain, truth))
            << drift_deg << "° " << to_string(source) << " σ² " << r.inflation << " " << r.closure_variance
            << " " << r.variance.message << " accepted " << r.accepted();
      else
        EXPECT_NEAR(worst_error(r.poses, truth), worst_error(chain, truth), 1e-6);  // nothing to close
    }
  }
}

TEST(LoopClosing, DescriptorCandidatesMustBeTrusted) {
  const PoseList truth = test::square_drive(2);
  std::vector<ChainStep> steps;
  const PoseList chain = drifted_chain(truth, 0.5 * M_PI / 180.0, &steps);
  LoopClosingSettings s;
  s.source = LoopCandidateSource::descriptor;
  Rng rng(3);
  const LoopClosingResult r = close_loops(odometry_graph(chain, steps).graph, true_places(),
                                          exact_registration(truth, false), s, rng);
  ASSERT_EQ(r.attempts.size(), true_places().size());
  EXPECT_EQ(r.accepted(), 0u);
  for (const ClosureAttempt& a : r.attempts) {
    EXPECT_EQ(a.source, LoopCandidateSource::descriptor);
    EXPECT_EQ(a.decision.rejection, ClosureRejection::untrusted);
    EXPECT_NE(a.decision.reason.find("made up"), std::string::npos);
  }
}

TEST(LoopClosing, SourceNamesRoundTrip) {
  for (const auto source :
       {LoopCandidateSource::proximity, LoopCandidateSource::descriptor, LoopCandidateSource::both}) {
    LoopCandidateSource back{};
    EXPECT_TRUE(from_string(to_string(source), &back));
    EXPECT_EQ(back, source);
  }
  LoopCandidateSource unchanged = LoopCandidateSource::descriptor;
  EXPECT_FALSE(from_string("nearby", &unchanged));
  EXPECT_EQ(unchanged, LoopCandidateSource::descriptor);
}

}  // namespace
}  // namespace sextant
