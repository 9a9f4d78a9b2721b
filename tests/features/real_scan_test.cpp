// Extraction on the real uos_3dtk scans (Kurt3D indoor scans, 3DTK): the large vertical walls
// are found in scan000 and scan001, and the walls of scan001 moved by the 3DTK registration
// (.frames, last line) coincide with those of scan000 (semantic association matches them).
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/io/uos.hpp"
#include "sextant/features/association.hpp"
#include "sextant/features/extraction.hpp"

namespace sextant {
namespace {

const std::string kDir = std::string(SEXTANT_DATA_DIR) + "/uos_3dtk/";

PlaneExtraction extract(const std::string& scan) {
  const PointCloud cloud = read_cloud(kDir + scan + ".3d");
  PlaneExtractionSettings s;
  s.cell_size = 1.0;
  s.min_landmark_area = 4.0;
  s.min_landmark_inliers = 500;
  Rng rng(1);
  return extract_planes(cloud, s, rng);
}

void print(const char* name, const PlaneExtraction& out) {
  std::printf("%s: %zu points → %zu cell planes → %zu landmarks (%zu horizontal removed)\n", name,
              out.stats.points, out.stats.cell_planes, out.landmarks.size(), out.stats.horizontal_removed);
  for (const auto& l : out.landmarks) {
    std::printf("  n = (%6.3f %6.3f %6.3f) d = %6.2f m  c = (%6.2f %6.2f %6.2f)  A = %6.1f m²  k = %zu\n",
                l.plane.normal.x(), l.plane.normal.y(), l.plane.normal.z(), l.plane.d, l.centroid.x(),
                l.centroid.y(), l.centroid.z(), l.area, l.inlier_count);
  }
}

TEST(RealScan, Uos3dtkWallsAreFoundAndConsistentBetweenScans) {
  const PlaneExtraction s0 = extract("scan000"), s1 = extract("scan001");
  print("scan000", s0);
  print("scan001", s1);
  ASSERT_GE(s0.landmarks.size(), 2u);
  ASSERT_GE(s1.landmarks.size(), 2u);
  for (const auto* out : {&s0, &s1}) {
    for (const auto& l : out->landmarks) {
      EXPECT_LT(std::abs(l.plane.normal.z()), std::sin(20.0 * M_PI / 180.0));  // vertical walls only
      EXPECT_LT(std::abs(l.plane.d), 30.0);                                    // within the building
    }
    // The two walls of the corridor, parallel and facing each other: y ≈ −0.97 m (the largest
    // landmark, normal +y towards the robot) and y ≈ +3.8 m (normal −y).
    const PlaneLandmark& right = out->landmarks.front();
    EXPECT_GT(right.plane.normal.y(), 0.99);
    EXPECT_NEAR(right.plane.d, -0.97, 0.1);
    bool left = false;
    for (const auto& l : out->landmarks)
      left |= l.plane.normal.y() < -0.99 && std::abs(l.plane.d + 3.78) < 0.1;
    EXPECT_TRUE(left);
  }
  // scan001 in scan000's frame with the 3DTK registration: the largest walls coincide.
  const Eigen::Isometry3d T0 = read_uos_frames(kDir + "scan000.frames").back();
  const Eigen::Isometry3d T1 = read_uos_frames(kDir + "scan001.frames").back();
  const auto world0 = transform_landmarks(s0.landmarks, T0), world1 = transform_landmarks(s1.landmarks, T1);
  const AssociationResult r = associate_landmarks(world1, world0, AssociationSettings{});
  std::printf("scan001 → scan000 with .frames: %zu of %zu walls matched\n", r.matches.size(), world1.size());
  std::size_t tight = 0;  // walls that coincide within 3° and 10 cm after the 3DTK registration
  for (const auto& m : r.matches) {
    std::printf("  obs %zu ↔ map %zu: C_o %.2f° C_t %.3f m C_p %.2f\n", m.observed, m.map,
                m.criteria.orientation_deg, m.criteria.translation, m.criteria.closeness);
    tight += m.criteria.orientation_deg < 3.0 && m.criteria.translation < 0.1;
  }
  EXPECT_GE(tight, 3u);
}

}  // namespace
}  // namespace sextant
