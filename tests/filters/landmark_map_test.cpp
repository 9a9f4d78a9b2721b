// The copy-on-write landmark map of FastSLAM (landmark_map.hpp): contents, sharing between
// copies, isolation of writes, and the O(log M) cost of a write.
#include <gtest/gtest.h>

#include "sextant/filters/landmark_map.hpp"

namespace sextant {
namespace {

LandmarkEkf ekf_of(double value) {
  return LandmarkEkf{Eigen::VectorXd::Constant(2, value), Eigen::MatrixXd::Identity(2, 2) * value, nullptr};
}

LandmarkMap map_of(int size, MapCounters* counters = nullptr) {
  LandmarkMap map;
  for (int i = 0; i < size; ++i) map.push_back(ekf_of(i), counters);
  return map;
}

TEST(LandmarkMap, StoresEveryLandmarkAcrossDepths) {
  for (int size : {0, 1, 7, 8, 9, 64, 65, 600}) {
    const LandmarkMap map = map_of(size);
    ASSERT_EQ(map.size(), size);
    for (int i = 0; i < size; ++i) EXPECT_EQ(map.get(i).mean[0], i) << size << " " << i;
  }
  EXPECT_EQ(map_of(8).depth(), 1);
  EXPECT_EQ(map_of(9).depth(), 2);
  EXPECT_EQ(map_of(65).depth(), 3);
}

TEST(LandmarkMap, CopyCopiesNoNodeAndNoLandmark) {
  MapCounters counters;
  const LandmarkMap original = map_of(100, &counters);
  const MapCounters before = counters;
  std::vector<LandmarkMap> copies(50, original);  // as resampling 50 particles from one
  EXPECT_EQ(counters.landmarks_written, before.landmarks_written);
  EXPECT_EQ(counters.nodes_copied, before.nodes_copied);
  for (const LandmarkMap& copy : copies)
    for (int i = 0; i < 100; ++i) EXPECT_EQ(copy.share(i).get(), original.share(i).get());
}

TEST(LandmarkMap, WriteChangesOnlyItsOwnCopyAndCopiesOnlyOnePath) {
  MapCounters counters;
  const LandmarkMap original = map_of(600, &counters);  // depth 4 (8⁴ = 4096 ≥ 600 > 512)
  ASSERT_EQ(original.depth(), 4);
  LandmarkMap sibling = original;
  LandmarkMap changed = original;
  const MapCounters before = counters;
  changed.set(321, ekf_of(-1.0), &counters);
  EXPECT_EQ(counters.landmarks_written - before.landmarks_written, 1u);
  EXPECT_EQ(counters.nodes_copied - before.nodes_copied, 4u);  // one node per level
  EXPECT_EQ(changed.get(321).mean[0], -1.0);
  EXPECT_EQ(sibling.get(321).mean[0], 321.0);
  EXPECT_EQ(original.get(321).mean[0], 321.0);
  for (int i = 0; i < 600; ++i) {
    if (i == 321) continue;
    EXPECT_EQ(changed.share(i).get(), original.share(i).get()) << i;
  }
  // And the other way round: a sibling's write is not seen by the changed copy.
  sibling.set(5, ekf_of(-5.0));
  EXPECT_EQ(changed.get(5).mean[0], 5.0);
  EXPECT_EQ(sibling.get(321).mean[0], 321.0);
}

TEST(LandmarkMap, PushBackOnACopyLeavesTheOriginal) {
  const LandmarkMap original = map_of(64);  // full at depth 2: the next push grows a level
  LandmarkMap grown = original;
  grown.push_back(ekf_of(64.0));
  EXPECT_EQ(original.size(), 64);
  EXPECT_EQ(original.depth(), 2);
  EXPECT_EQ(grown.size(), 65);
  EXPECT_EQ(grown.get(64).mean[0], 64.0);
  EXPECT_EQ(grown.share(10).get(), original.share(10).get());
}

}  // namespace
}  // namespace sextant
