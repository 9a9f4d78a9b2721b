#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sextant/core/rng.hpp"
#include "sextant/features/hull.hpp"
#include "sextant/features/landmark.hpp"
#include "sextant/features/plane_fit.hpp"
#include "sextant_test/random_draws.hpp"

namespace sextant {
namespace {

std::vector<Eigen::Vector3f> noisy_plane_points(const Plane& plane, std::size_t n, double noise, Rng& rng) {
  const Eigen::Vector3d u = plane.normal.unitOrthogonal(), v = plane.normal.cross(u);
  std::vector<Eigen::Vector3f> out;
  for (std::size_t i = 0; i < n; ++i) {
    const double along_v = rng.uniform(-2, 2), along_u = rng.uniform(-3, 3), offset = rng.normal(0, noise);
    const Eigen::Vector3d p = plane.normal * (plane.d + offset) + u * along_u + v * along_v;
    out.push_back(p.cast<float>());
  }
  return out;
}

std::vector<std::size_t> all_indices(std::size_t n) {
  std::vector<std::size_t> idx(n);
  for (std::size_t i = 0; i < n; ++i) idx[i] = i;
  return idx;
}

TEST(PlaneFit, PcaAndSvdRecoverAKnownPlane) {
  Rng rng(7);
  const Plane truth{Eigen::Vector3d(1, 2, 0.5).normalized(), 4.0};
  const auto points = noisy_plane_points(truth, 500, 0.005, rng);
  for (PlaneRefit method : {PlaneRefit::pca, PlaneRefit::svd}) {
    const PlaneFit fit = fit_plane(points, all_indices(points.size()), method);
    ASSERT_TRUE(fit.ok);
    Plane p = fit.plane;
    if (p.normal.dot(truth.normal) < 0) p.normal = -p.normal, p.d = -p.d;
    EXPECT_NEAR(p.normal.dot(truth.normal), 1.0, 1e-4);
    EXPECT_NEAR(p.d, truth.d, 2e-3);
    EXPECT_NEAR(p.normal.norm(), 1.0, 1e-12);
  }
}

TEST(PlaneFit, ExactPlaneWithoutNoiseIsExact) {
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) points.emplace_back(float(i), float(j), 2.0f);  // z = 2
  for (PlaneRefit method : {PlaneRefit::pca, PlaneRefit::svd}) {
    const PlaneFit fit = fit_plane(points, all_indices(points.size()), method);
    ASSERT_TRUE(fit.ok);
    EXPECT_NEAR(std::abs(fit.plane.normal.z()), 1.0, 1e-12);
    EXPECT_NEAR(std::abs(fit.plane.d), 2.0, 1e-9);
  }
}

TEST(PlaneFit, CollinearAndTooFewPointsAreNotPlanes) {
  std::vector<Eigen::Vector3f> line;
  for (int i = 0; i < 20; ++i) line.emplace_back(float(i), float(2 * i), 1.0f);
  EXPECT_FALSE(fit_plane(line, all_indices(line.size()), PlaneRefit::pca).ok);
  EXPECT_FALSE(fit_plane(line, {0, 1}, PlaneRefit::pca).ok);
  EXPECT_FALSE(fit_plane(line, {}, PlaneRefit::svd).ok);
}

TEST(PointMoments, CombineEqualsMomentsOfTheUnion) {
  Rng rng(3);
  std::vector<Eigen::Vector3d> a, b, all;
  for (int i = 0; i < 40; ++i) {
    const Eigen::Vector3d n = test::normal_draws<3>(rng);
    a.emplace_back(n.x(), 1 + 2 * n.y(), -3 + 0.5 * n.z());
  }
  for (int i = 0; i < 25; ++i) b.push_back(test::normal_draws<3>(rng) + Eigen::Vector3d(4, 0, 0));
  all = a;
  all.insert(all.end(), b.begin(), b.end());
  const PointMoments c = PointMoments::combine(compute_moments(a), compute_moments(b));
  const PointMoments d = compute_moments(all);
  EXPECT_EQ(c.count, d.count);
  EXPECT_LT((c.centroid - d.centroid).norm(), 1e-12);
  EXPECT_LT((c.covariance() - d.covariance()).norm(), 1e-10);
  const PointMoments e = PointMoments::from_covariance(d.count, d.centroid, d.covariance());
  EXPECT_LT((e.scatter - d.scatter).norm(), 1e-9);
}

TEST(Hull, SquareWithInteriorAndEdgePoints) {
  std::vector<Eigen::Vector2d> pts = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}, {1, 0}, {0.5, 1.5}, {2, 2}};
  const auto hull = convex_hull_2d(pts);
  ASSERT_EQ(hull.size(), 4u);
  EXPECT_NEAR(polygon_area(hull), 4.0, 1e-12);  // counter-clockwise → positive
  const Rectangle2d rect = min_area_rectangle(hull);
  EXPECT_NEAR(rect.area, 4.0, 1e-12);
}

TEST(Hull, MinAreaRectangleOfARotatedRectangle) {
  const double a = 0.4;
  const Eigen::Vector2d u(std::cos(a), std::sin(a)), v(-std::sin(a), std::cos(a));
  Rng rng(5);
  std::vector<Eigen::Vector2d> pts = {Eigen::Vector2d::Zero(), 3 * u, 3 * u + 1 * v, 1 * v};
  for (int i = 0; i < 50; ++i) {
    const double along_v = rng.uniform(0, 1), along_u = rng.uniform(0, 3);
    pts.push_back(along_u * u + along_v * v);
  }
  const auto hull = convex_hull_2d(pts);
  EXPECT_EQ(hull.size(), 4u);
  const Rectangle2d rect = min_area_rectangle(hull);
  EXPECT_NEAR(rect.area, 3.0, 1e-9);
  ASSERT_EQ(rect.corners.size(), 4u);
  // The axis-aligned box would be much larger than the rotated one.
  EXPECT_NEAR(std::abs(polygon_area(rect.corners)), 3.0, 1e-9);
}

TEST(Hull, DegenerateInputs) {
  EXPECT_TRUE(convex_hull_2d({}).empty());
  EXPECT_EQ(convex_hull_2d({{1, 1}, {1, 1}, {1, 1}}).size(), 1u);
  const auto line = convex_hull_2d({{0, 0}, {1, 1}, {2, 2}, {3, 3}});
  EXPECT_EQ(line.size(), 2u);
  EXPECT_EQ(polygon_area(line), 0.0);
  EXPECT_EQ(convex_hull_2d({{0, 0}, {NAN, 1}, {1, 0}, {0, 1}}).size(), 3u);
  EXPECT_EQ(min_area_rectangle({}).area, 0.0);
}

TEST(Outline, ProjectionAndBackProjectionOfATiltedRectangle) {
  // A 4 m × 2 m rectangle on a tilted plane: hull area 8, hull vertices on the plane (eq. (3.32)).
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, -1, 0.2).normalized();
  const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u), origin(1, 2, 3);
  std::vector<Eigen::Vector3f> pts;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 4; ++j) pts.push_back((origin + u * (0.5 * i) + v * (0.5 * j)).cast<float>());
  std::vector<std::size_t> idx = all_indices(pts.size());
  const PlaneFit fit = fit_plane(pts, idx, PlaneRefit::pca);
  ASSERT_TRUE(fit.ok);
  const PlaneLandmark l = make_landmark(pts, idx, fit, origin + 5 * n);
  EXPECT_NEAR(l.area, 8.0, 1e-4);
  EXPECT_GE(l.hull.size(), 4u);             // float rounding may keep a few nearly collinear edge points
  EXPECT_GT(l.plane.normal.dot(n), 0.999);  // oriented towards the viewpoint
  for (const auto& p : l.hull) EXPECT_NEAR(l.plane.signed_distance(p), 0.0, 1e-5);
  ASSERT_EQ(l.rectangle.size(), 4u);
  EXPECT_NEAR((l.rectangle[1] - l.rectangle[0]).norm() * (l.rectangle[2] - l.rectangle[1]).norm(), 8.0, 1e-4);
}

TEST(Landmark, TransformMatchesTransformingThePoints) {
  Rng rng(11);
  const Plane truth{Eigen::Vector3d(0, 1, 0.1).normalized(), 3.0};
  const auto pts = noisy_plane_points(truth, 200, 0.01, rng);
  const auto idx = all_indices(pts.size());
  const PlaneLandmark l =
      make_landmark(pts, idx, fit_plane(pts, idx, PlaneRefit::pca), Eigen::Vector3d::Zero());
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(5, -2, 1);
  const PlaneLandmark lt = l.transformed(T);

  std::vector<Eigen::Vector3f> moved;
  for (const auto& p : pts) moved.push_back((T * p.cast<double>()).cast<float>());
  const PlaneLandmark direct =
      make_landmark(moved, idx, fit_plane(moved, idx, PlaneRefit::pca), T.translation());
  EXPECT_GT(lt.plane.normal.dot(direct.plane.normal), 1.0 - 1e-9);
  EXPECT_NEAR(lt.plane.d, direct.plane.d, 1e-5);
  EXPECT_LT((lt.centroid - direct.centroid).norm(), 1e-5);
  EXPECT_LT((lt.covariance - direct.covariance).norm(), 1e-5);  // R Σ Rᵀ (eq. (4.59))
  for (const auto& p : lt.hull) EXPECT_NEAR(lt.plane.signed_distance(p), 0.0, 1e-4);
  EXPECT_NEAR(lt.area, l.area, 1e-9);
}

}  // namespace
}  // namespace sextant
