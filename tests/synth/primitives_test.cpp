// Known-answer ray intersections for every primitive of the synthetic world.
#include <gtest/gtest.h>

#include <cmath>

#include "sextant/synth/primitives.hpp"

namespace sextant::synth {
namespace {

Ray ray_x(double y = 0.0, double z = 0.0) {
  return Ray{{0, y, z}, {1, 0, 0}};
}

TEST(Primitives, PolygonHitInsideMissOutsideAndHasRightHandNormal) {
  // Square in the plane x = 5, vertices ordered so the normal points to −x (towards the origin).
  const Polygon square({{5, -1, -1}, {5, -1, 1}, {5, 1, 1}, {5, 1, -1}});
  EXPECT_NEAR(square.normal().x(), -1.0, 1e-12);
  EXPECT_NEAR(square.d(), -5.0, 1e-12);
  EXPECT_NEAR(square.area(), 4.0, 1e-12);
  ASSERT_TRUE(square.intersect(ray_x(0.5, 0.5), 100));
  EXPECT_NEAR(*square.intersect(ray_x(0.5, 0.5), 100), 5.0, 1e-12);
  EXPECT_FALSE(square.intersect(ray_x(1.5, 0.0), 100));
  EXPECT_FALSE(square.intersect(ray_x(0.0, 0.0), 4.0));  // beyond max range
}

TEST(Primitives, NonConvexPolygonRejectsTheNotch) {
  // A U shape in z = 0 (notch 1 < x < 2, y > 1).
  const Polygon u({{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {2, 2, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}});
  EXPECT_TRUE(u.intersect(Ray{{0.5, 1.5, 1}, {0, 0, -1}}, 10));
  EXPECT_FALSE(u.intersect(Ray{{1.5, 1.5, 1}, {0, 0, -1}}, 10));
  EXPECT_NEAR(u.area(), 5.0, 1e-12);
}

TEST(Primitives, OrientedBoxRotatedByYaw) {
  const OrientedBox box{{10, 0, 0}, {2, 1, 1}, M_PI / 2};  // long axis along y after rotation
  ASSERT_TRUE(box.intersect(ray_x(), 100));
  EXPECT_NEAR(*box.intersect(ray_x(), 100), 9.0, 1e-9);
  EXPECT_TRUE(box.intersect(ray_x(1.5), 100));
  EXPECT_FALSE(box.intersect(ray_x(2.5), 100));
  EXPECT_NEAR(box.surface_distance({9, 0, 0}), 0.0, 1e-12);
}

TEST(Primitives, CylinderSideAndCap) {
  const Cylinder c{{5, 0}, 0.5, 0.0, 2.0};
  ASSERT_TRUE(c.intersect(ray_x(0, 1), 100));
  EXPECT_NEAR(*c.intersect(ray_x(0, 1), 100), 4.5, 1e-12);
  EXPECT_FALSE(c.intersect(ray_x(0, 3), 100));
  const auto top = c.intersect(Ray{{5.2, 0, 10}, {0, 0, -1}}, 100);
  ASSERT_TRUE(top);
  EXPECT_NEAR(*top, 8.0, 1e-12);
}

TEST(Primitives, EllipsoidSpan) {
  const Ellipsoid e{{10, 0, 0}, {2, 1, 1}};
  const auto s = e.span(ray_x(), 100);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->entry, 8.0, 1e-12);
  EXPECT_NEAR(s->exit, 12.0, 1e-12);
  EXPECT_FALSE(e.span(ray_x(1.5), 100));
}

TEST(Primitives, TriangleMollerTrumbore) {
  const Triangle t{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  const auto hit = t.intersect(Ray{{1, 1, 3}, {0, 0, -1}}, 10);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(*hit, 3.0, 1e-12);
  EXPECT_FALSE(t.intersect(Ray{{3, 3, 3}, {0, 0, -1}}, 10));
  EXPECT_NEAR(t.distance({1, 1, 0.25}), 0.25, 1e-12);
  EXPECT_NEAR(t.distance({-3, 0, 4}), 5.0, 1e-12);  // nearest point is the corner a
}

}  // namespace
}  // namespace sextant::synth
