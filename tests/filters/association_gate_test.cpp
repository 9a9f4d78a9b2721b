// The χ² innovation gate of data association and SEIF's Markov-blanket covariance behind it.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cstdio>
#include <map>

#include "plane_world.hpp"
#include "sextant/core/chi_square.hpp"
#include "sextant/filters/innovation_gate.hpp"
#include "sextant/filters/seif.hpp"
#include "sextant/filters/yaml.hpp"

namespace sextant {
namespace {

/// Rows of the pose and landmark j in the full state.
std::vector<Eigen::Index> pose_and_landmark_rows(const SlamModel& model, int j) {
  std::vector<Eigen::Index> rows;
  for (int k = 0; k < model.pose_dim(); ++k) rows.push_back(k);
  for (int k = 0; k < model.landmark_dim(); ++k) rows.push_back(landmark_offset(model, j) + k);
  return rows;
}

double smallest_eigenvalue(const Eigen::MatrixXd& M) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (M + M.transpose())).eigenvalues().minCoeff();
}

Seif seif_with_map(int planes, int max_active) {
  SeifSettings s;
  s.max_active_landmarks = max_active;
  Seif seif("seif", std::make_shared<PlaneSlamModel>(), s);
  test::grow_random_plane_map(seif, planes, 7);
  return seif;
}

TEST(MarkovBlanket, EifBlanketHoldsEveryVariableAndIsExact) {
  const test::PlaneWorld world = test::make_plane_world(12, 4);
  auto model = std::make_shared<PlaneSlamModel>();
  auto eif = make_filter("eif", model);
  const auto known = test::start_plane_slam(*eif, world);
  run_slam(*eif, world.steps, world.Q, world.R, {}, known);
  const auto& seif = dynamic_cast<const Seif&>(*eif);
  const Eigen::MatrixXd P = eif->covariance();
  for (int j = 0; j < eif->num_landmarks(); ++j) {
    EXPECT_EQ(static_cast<int>(seif.markov_blanket({j}).size()), eif->num_landmarks() + 1);
    const std::vector<Eigen::Index> rows = pose_and_landmark_rows(*model, j);
    const Eigen::MatrixXd exact = P(rows, rows);
    EXPECT_LT((eif->joint_covariance({j}) - exact).norm(), 1e-9 * exact.norm()) << j;
  }
}

// Conditioning on the rest of the map only removes uncertainty: the blanket covariance is never
// larger than the exact marginal of the same information matrix. For a landmark a fixed number
// of links from the pose the blanket, and so the cost, does not grow with the map; for an old
// landmark it holds the path back to the active set, which grows with the graph distance.
TEST(MarkovBlanket, SeifBlanketIsBoundedAndConditional) {
  std::map<int, std::vector<std::size_t>> sizes;  // planes → blanket sizes for the newest, recent, oldest
  for (int planes : {40, 160}) {
    const Seif seif = seif_with_map(planes, 4);
    const Eigen::MatrixXd P = seif.covariance();
    for (int j : {planes - 1, planes - 10, 0}) {
      sizes[planes].push_back(seif.markov_blanket({j}).size());
      const std::vector<Eigen::Index> rows = pose_and_landmark_rows(seif.model(), j);
      const Eigen::MatrixXd exact = P(rows, rows), blanket = seif.joint_covariance({j});
      EXPECT_GT(smallest_eigenvalue(blanket), 0.0) << planes << " " << j;
      EXPECT_GT(smallest_eigenvalue(exact - blanket), -1e-9 * exact.norm()) << planes << " " << j;
    }
  }
  std::printf(
      "[markov-blanket] blanket size (newest, 10 back, oldest landmark): 40 planes %zu %zu %zu, "
      "160 planes %zu %zu %zu\n",
      sizes[40][0], sizes[40][1], sizes[40][2], sizes[160][0], sizes[160][1], sizes[160][2]);
  EXPECT_EQ(sizes[160][0], sizes[40][0]);
  EXPECT_EQ(sizes[160][1], sizes[40][1]);
  EXPECT_GT(sizes[160][2], sizes[40][2]);
}

TEST(MarkovBlanket, JointCovarianceOfSeveralLandmarksAndBadIndices) {
  const Seif seif = seif_with_map(20, 4);
  const Eigen::MatrixXd P = seif.covariance();
  const Eigen::MatrixXd two = seif.joint_covariance({19, 18});  // both active: the blanket is exact
  EXPECT_EQ(two.rows(), 6 + 2 * 4);
  std::vector<Eigen::Index> rows = pose_and_landmark_rows(seif.model(), 19);
  for (int k = 0; k < 4; ++k) rows.push_back(landmark_offset(seif.model(), 18) + k);
  EXPECT_GT(smallest_eigenvalue(P(rows, rows) - two), -1e-9 * two.norm());
  EXPECT_THROW(seif.joint_covariance({20}), std::out_of_range);
  EXPECT_THROW(seif.markov_blanket({-1}), std::out_of_range);
}

struct GateCounts {
  std::size_t correct = 0, correct_passed = 0, wrong = 0, wrong_passed = 0;
};

/// Runs the plane world and, before every update, gates each observation against its own plane
/// and against the next plane.
GateCounts gate_over_run(Filter& filter, const test::PlaneWorld& world, double gate) {
  const auto known = test::start_plane_slam(filter, world);
  GateCounts c;
  for (const SlamStepInput& step : world.steps) {
    EXPECT_TRUE(filter.predict(step.u, world.Q).ok());
    std::vector<Eigen::VectorXd> zs;
    std::vector<int> ids;
    for (const SlamObservation& o : step.observations) {
      const int own = known.at(o.landmark),
                other = known.at((o.landmark + 1) % static_cast<int>(known.size()));
      ++c.correct, ++c.wrong;
      if (innovation_distance(filter, o.z, world.R, own) <= gate) ++c.correct_passed;
      if (innovation_distance(filter, o.z, world.R, other) <= gate) ++c.wrong_passed;
      zs.push_back(o.z);
      ids.push_back(own);
    }
    EXPECT_TRUE(filter.update(zs, world.R, ids).ok());
  }
  return c;
}

TEST(InnovationGate, PassesTrueAssociationsAndRejectsWrongOnes) {
  const test::PlaneWorld world = test::make_plane_world(40, 9);
  const double gate = chi_square_quantile(0.99, 4);
  auto model = std::make_shared<PlaneSlamModel>();
  for (const std::string name : {"ekf", "ukf", "seif"}) {
    const YAML::Node settings = name == "seif" ? YAML::Load("{max_active_landmarks: 3}") : YAML::Node();
    auto filter = make_filter(name, model, settings);
    const GateCounts c = gate_over_run(*filter, world, gate);
    std::printf("[gate 0.99] %-4s true associations passed %zu/%zu, wrong ones passed %zu/%zu\n",
                name.c_str(), c.correct_passed, c.correct, c.wrong_passed, c.wrong);
    EXPECT_GE(c.correct_passed, c.correct * 95 / 100) << name;
    EXPECT_EQ(c.wrong_passed, 0u) << name;
  }
}

TEST(InnovationGate, NonFiniteObservationIsFar) {
  auto model = std::make_shared<PlaneSlamModel>();
  auto ekf = make_filter("ekf", model);
  const test::PlaneWorld world = test::make_plane_world(2, 1);
  test::start_plane_slam(*ekf, world);
  Eigen::VectorXd z = world.first_observations[0];
  EXPECT_LT(innovation_distance(*ekf, z, world.R, 0), chi_square_quantile(0.99, 4));
  z[3] = std::nan("");
  EXPECT_TRUE(std::isinf(innovation_distance(*ekf, z, world.R, 0)));
}

}  // namespace
}  // namespace sextant
