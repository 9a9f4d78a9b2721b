#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/features/association.hpp"
#include "sextant/features/extraction.hpp"
#include "sextant/features/yaml.hpp"
#include "synthetic_scene.hpp"

namespace sextant {
namespace {

using test::Scene;
using test::Wall;

constexpr double kNormalTolDeg = 3.0;
constexpr double kDistanceTol = 0.05;

/// Index of the true wall a world-frame landmark belongs to (normal within 3°, d within 5 cm,
/// centroid on the wall), or −1.
int label(const PlaneLandmark& l, const Scene& scene) {
  for (std::size_t w = 0; w < scene.walls.size(); ++w) {
    const Plane truth = scene.walls[w].plane();
    const double dot = l.plane.normal.dot(truth.normal);
    const double angle = std::acos(std::min(1.0, std::abs(dot))) * 180.0 / M_PI;
    const double d = dot < 0 ? -l.plane.d : l.plane.d;
    if (angle < kNormalTolDeg && std::abs(d - truth.d) < kDistanceTol &&
        scene.walls[w].contains(l.centroid, 1.0))
      return static_cast<int>(w);
  }
  return -1;
}

struct Score {
  double precision = 0, recall = 0;
  std::size_t landmarks = 0;
};

Score score(const std::vector<PlaneLandmark>& world_landmarks, const Scene& scene) {
  Score s;
  std::vector<bool> found(scene.walls.size(), false);
  std::size_t correct = 0;
  for (const auto& l : world_landmarks) {
    const int w = label(l, scene);
    if (w >= 0) ++correct, found[static_cast<std::size_t>(w)] = true;
  }
  s.landmarks = world_landmarks.size();
  s.precision = s.landmarks ? double(correct) / double(s.landmarks) : 0.0;
  s.recall = double(std::count(found.begin(), found.end(), true)) / double(scene.walls.size());
  return s;
}

Eigen::Isometry3d pose(double x, double y, double z, double yaw_deg) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

TEST(Extraction, RecoversTheWallsOfASyntheticScene) {
  const Scene scene = test::courtyard();
  const Eigen::Isometry3d sensor = pose(1.0, -2.0, 1.5, 25.0);
  Rng rng(42);
  const PointCloud cloud = test::sample_scene(scene, sensor, rng);
  Rng ransac(1);
  const PlaneExtraction out = extract_planes(cloud, PlaneExtractionSettings{}, ransac);
  const Score s = score(transform_landmarks(out.landmarks, sensor), scene);
  const auto& st = out.stats;
  std::printf(
      "scene: %zu points, %zu cells (%zu too few, %zu duplicated, %zu collinear, %zu without plane), "
      "%zu cell planes → %zu merged → %zu horizontal, %zu small removed → %zu landmarks; "
      "precision %.2f recall %.2f; %.1f ms\n",
      st.points, st.cells, st.cells_too_few_points, st.cells_duplicated_points, st.cells_collinear,
      st.cells_without_plane, st.cell_planes, st.merged_planes, st.horizontal_removed, st.too_small_removed,
      st.landmarks, s.precision, s.recall, st.seconds * 1e3);
  EXPECT_GE(s.recall, 1.0);     // every wall found
  EXPECT_GE(s.precision, 0.9);  // few landmarks on clutter or split walls off the true plane
  EXPECT_GE(st.horizontal_removed, 1u);
  EXPECT_LE(out.landmarks.size(), 2 * scene.walls.size());
  for (const auto& l : out.landmarks) {
    EXPECT_GE(l.inlier_count, PlaneExtractionSettings{}.min_landmark_inliers);
    EXPECT_EQ(l.inliers.size(), l.inlier_count);
    EXPECT_GE(l.plane.signed_distance(Eigen::Vector3d::Zero()), 0.0);  // normals face the sensor
  }
  // The fbs sample: plane inliers only, a fraction of the cloud.
  const auto fbs = out.cell_inlier_indices();
  EXPECT_GT(fbs.size(), cloud.size() / 3);
  EXPECT_LT(fbs.size(), cloud.size());
}

TEST(Extraction, SameSeedSameResult) {
  const Scene scene = test::courtyard();
  Rng rng(4);
  const PointCloud cloud = test::sample_scene(scene, pose(0, 0, 1, 0), rng, 4.0, 1.0, 100);
  Rng a(9), b(9);
  const PlaneExtraction x = extract_planes(cloud, {}, a), y = extract_planes(cloud, {}, b);
  ASSERT_EQ(x.landmarks.size(), y.landmarks.size());
  for (std::size_t i = 0; i < x.landmarks.size(); ++i) {
    EXPECT_EQ(x.landmarks[i].plane.normal, y.landmarks[i].plane.normal);
    EXPECT_EQ(x.landmarks[i].inliers, y.landmarks[i].inliers);
  }
}

TEST(Extraction, DegenerateCellsAreSkippedAndCounted) {
  PointCloud cloud;
  // Cell (0,0,0): 5 points — too few.
  for (int i = 0; i < 5; ++i) cloud.push_back(Eigen::Vector3f(0.1f + 0.1f * i, 0.5f, 0.15f * i));
  // Cell (1,0,0): 30 copies of 3 points — duplicated.
  for (int i = 0; i < 30; ++i)
    cloud.push_back(Eigen::Vector3f(1.1f + 0.3f * (i % 3), 0.2f, 0.4f * (i % 3 == 1)));
  // Cell (2,0,0): 40 points on a line — collinear.
  for (int i = 0; i < 40; ++i) cloud.push_back(Eigen::Vector3f(2.05f + 0.02f * i, 0.1f + 0.02f * i, 0.5f));
  // Cell (3,0,0): a planar patch of 49 points — one plane.
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j) cloud.push_back(Eigen::Vector3f(3.05f + 0.13f * i, 0.5f, 0.05f + 0.13f * j));
  // Non-finite points are skipped and counted.
  cloud.push_back(Eigen::Vector3f(std::numeric_limits<float>::quiet_NaN(), 0.f, 0.f));
  cloud.push_back(Eigen::Vector3f(0.f, std::numeric_limits<float>::infinity(), 0.f));
  PlaneExtractionSettings s;
  s.cell_size = 1.0;
  s.min_landmark_area = 0.1;
  Rng rng(3);
  const PlaneExtraction out = extract_planes(cloud, s, rng);
  EXPECT_EQ(out.stats.non_finite_points, 2u);
  EXPECT_EQ(out.stats.cells, 4u);
  EXPECT_EQ(out.stats.cells_too_few_points, 1u);
  EXPECT_EQ(out.stats.cells_duplicated_points, 1u);
  EXPECT_EQ(out.stats.cells_collinear, 1u);
  EXPECT_EQ(out.stats.cells_without_plane, 0u);
  ASSERT_EQ(out.stats.cell_planes, 1u);
  EXPECT_EQ(out.cell_planes[0].inlier_count, 49u);
  EXPECT_NEAR(std::abs(out.cell_planes[0].plane.normal.y()), 1.0, 1e-6);
  EXPECT_EQ(out.landmarks.size(), 1u);
}

TEST(Extraction, EmptyAndAllNanCloudsGiveNothing) {
  Rng rng(1);
  EXPECT_TRUE(extract_planes(PointCloud(), {}, rng).landmarks.empty());
  PointCloud nan;
  for (int i = 0; i < 100; ++i)
    nan.push_back(Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN()));
  const PlaneExtraction out = extract_planes(nan, {}, rng);
  EXPECT_EQ(out.stats.non_finite_points, 100u);
  EXPECT_EQ(out.stats.cells, 0u);
}

TEST(Extraction, SvdRefitFindsTheSameWalls) {
  const Scene scene = test::courtyard();
  Rng rng(8);
  const PointCloud cloud = test::sample_scene(scene, Eigen::Isometry3d::Identity(), rng);
  PlaneExtractionSettings s;
  s.refit = "svd";
  Rng ransac(2);
  const Score sc = score(extract_planes(cloud, s, ransac).landmarks, scene);
  EXPECT_GE(sc.recall, 1.0);
  EXPECT_GE(sc.precision, 0.9);
}

TEST(ExtractionSettings, YamlMappingAndErrors) {
  const YAML::Node node =
      YAML::Load("cell_size: 1.5\nrefit: svd\nmin_inliers: 12\nmerge_thresholds:\n  orientation_deg: 10\n");
  const PlaneExtractionSettings s = read_plane_extraction_settings(node, "e.yaml");
  EXPECT_EQ(s.cell_size, 1.5);
  EXPECT_EQ(s.refit, "svd");
  EXPECT_EQ(s.min_inliers, 12u);
  EXPECT_EQ(s.merge_thresholds.orientation_deg, 10.0);
  EXPECT_EQ(s.merge_thresholds.translation, 0.75);
  EXPECT_THROW(read_plane_extraction_settings(YAML::Load("cell_sise: 1"), "e.yaml"), InputError);
  EXPECT_THROW(read_plane_extraction_settings(YAML::Load("refit: lsq"), "e.yaml"), InputError);
  EXPECT_THROW(read_plane_extraction_settings(YAML::Load("cell_size: -1"), "e.yaml"), InputError);
  EXPECT_THROW(read_plane_extraction_settings(YAML::Load("merge_thresholds: {t: 1}"), "e.yaml"), InputError);
  try {
    read_plane_extraction_settings(YAML::Load("a: 1\nmin_inliers: x\n"), "e.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "e.yaml");
    EXPECT_NE(std::string(e.what()).find("min_inliers"), std::string::npos);
  }
  PlaneExtractionSettings bad;
  bad.ransac_iterations = 0;
  std::string why;
  EXPECT_FALSE(bad.valid(&why));
  Rng rng(1);
  EXPECT_THROW(extract_planes(PointCloud(), bad, rng), std::invalid_argument);
}

// Consecutive scans with the true relative pose: observed landmarks of scan 2, moved to the
// world, matched against scan 1's landmarks.
TEST(Association, ConsecutiveScansMatchTheSameTruePlanes) {
  const Scene scene = test::courtyard();
  std::size_t matches = 0, correct = 0, scans = 0;
  const std::vector<Eigen::Isometry3d> poses = {pose(0, 0, 1.5, 0), pose(2.0, 1.0, 1.5, 12),
                                                pose(3.5, 3.0, 1.6, 30), pose(2.0, 5.0, 1.5, 60)};
  Rng rng(100);
  std::vector<PlaneLandmark> previous;
  for (const auto& T : poses) {
    const PointCloud cloud = test::sample_scene(scene, T, rng);
    const std::vector<PlaneLandmark> world = transform_landmarks(extract_planes(cloud, {}, rng).landmarks, T);
    if (!previous.empty()) {
      const AssociationResult r = associate_landmarks(world, previous, AssociationSettings{});
      for (const auto& m : r.matches) {
        ++matches;
        const int a = label(world[m.observed], scene), b = label(previous[m.map], scene);
        if (a >= 0 && a == b) ++correct;
      }
      EXPECT_EQ(r.matches.size() + r.new_landmarks.size(), world.size());
      ++scans;
    }
    previous = world;
  }
  const double precision = matches ? double(correct) / double(matches) : 0.0;
  std::printf("association over %zu scan pairs: %zu matches, precision %.3f\n", scans, matches, precision);
  EXPECT_GE(matches, 3 * scene.walls.size() * 2 / 3);
  EXPECT_GE(precision, 0.95);
}

TEST(Association, LinearIndexFindsOnlyNearbyCandidates) {
  std::vector<PlaneLandmark> map;
  for (int i = 0; i < 100; ++i) {
    PlaneLandmark l;
    l.plane = Plane{Eigen::Vector3d::UnitX(), 10.0 * i};
    l.centroid = Eigen::Vector3d(10.0 * i, 0, 2);
    l.covariance = Eigen::Vector3d(1e-4, 4, 2).asDiagonal();
    l.inlier_count = 100;
    map.push_back(l);
  }
  std::vector<PlaneLandmark> observed = {map[42], map[7]};
  observed[0].centroid += Eigen::Vector3d(0.02, 0.5, 0.1);
  observed[0].plane.d += 0.02;
  PlaneLandmark unknown = map[0];
  unknown.centroid = Eigen::Vector3d(5000, 5000, 0);
  unknown.plane.d = 5000;
  observed.push_back(unknown);
  AssociationSettings s;
  s.search_radius = 20.0;
  const AssociationResult r = associate_landmarks(observed, map, s);
  ASSERT_EQ(r.matches.size(), 2u);
  EXPECT_EQ(r.matches[0].map, 42u);
  EXPECT_EQ(r.matches[1].map, 7u);
  EXPECT_EQ(r.new_landmarks, (std::vector<std::size_t>{2}));
  EXPECT_LE(r.candidates_tested, 10u);  // only centroids within 20 m (5 + 5)
}

TEST(AssociationSettings, Yaml) {
  const AssociationSettings s =
      read_association_settings(YAML::Load("search_radius: 12\norientation_deg: 25\n"), "a.yaml");
  EXPECT_EQ(s.search_radius, 12.0);
  EXPECT_EQ(s.thresholds.orientation_deg, 25.0);
  EXPECT_EQ(s.thresholds.translation, 1.0);
  EXPECT_THROW(read_association_settings(YAML::Load("radius: 12"), "a.yaml"), InputError);
  EXPECT_THROW(read_association_settings(YAML::Load("search_radius: 0"), "a.yaml"), InputError);
}

}  // namespace
}  // namespace sextant
