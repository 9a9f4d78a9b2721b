// Odometry on a real sequence (issue 22): a short stretch of the shared MulRan Riverside02 excerpt
// (Ouster OS1-64 on a car; ../shared/data, whose reference is good to a few cm on 0–107), read as a
// plain folder of scans. Right or say so: no step more than 1 m or 5° off the reference is trusted.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "sextant/core/dataset.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/core/units.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/sampler.hpp"
#include "sextant/matchers/yaml.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant_test/temp_dir.hpp"

namespace sextant {
namespace {

const std::filesystem::path kMulran = std::filesystem::path(SEXTANT_SHARED_DATA_DIR) / "mulran_riverside02";

/// The trusted steps of `r` (scans first, first + 1, …), each expected within 1 m and 5° of the
/// reference's relative motion.
std::size_t trusted_steps_expecting_them_right(const Dataset& dataset, const OdometryResult& r,
                                               std::size_t first) {
  std::size_t trusted = 0;
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    if (!r.steps[i].trusted()) continue;
    ++trusted;
    const Eigen::Isometry3d truth =
        relative(*dataset.ground_truth(first + i), *dataset.ground_truth(first + i + 1));
    const Eigen::Isometry3d error = relative(truth, r.steps[i].relative);
    const bool wrong = translation_norm(error) > 1.0 || rotation_angle(error) * kDegPerRad > 5.0;
    EXPECT_FALSE(wrong) << "step " << first + i << " is " << translation_norm(error)
                        << " m off and says trusted";
  }
  return trusted;
}

TEST(RealSequence, MulranStretchIsRightOrSaysSo) {
  if (!std::filesystem::is_directory(kMulran)) GTEST_SKIP() << "no " << kMulran;
  const auto dataset = open_dataset(kMulran);
  ASSERT_EQ(dataset->metadata().format, "folder");
  ASSERT_EQ(dataset->size(), 166u);
  ASSERT_TRUE(dataset->metadata().has_ground_truth);
  ASSERT_TRUE(dataset->stamp(0).has_value());
  // Keyframes 26–40: the car speeds up to 10 m/s, keyframes 3–14 m apart, 0.3–1.4 s.
  OdometrySettings s;
  s.guess = OdometryGuess::constant_velocity;
  s.map = OdometryMap::scan;
  const std::size_t first = 26, count = 15;
  const OdometryResult r = run_odometry(*dataset, s, first, count);
  ASSERT_EQ(r.steps.size(), count - 1);
  const std::size_t trusted = trusted_steps_expecting_them_right(*dataset, r, first);
  for (const OdometryStep& step : r.steps) {
    if (!step.trusted()) {
      EXPECT_FALSE(step.recovery.empty()) << "an untrusted step records how it was chained";
    }
  }
  EXPECT_GE(trusted, count / 2) << "most steps of a drive are registered and believed";
  EXPECT_EQ(r.untrusted(), r.steps.size() - trusted);
  // Keyframes 31→32 (0.5 s, 7.9 m, where the last trusted motion says 14 m): the registration from
  // the constant-velocity guess is not trusted, so the step is recovered (with the precision stage
  // the wide basin finds a trusted pose; before it, only the least suspect registration was left)
  // and lands within 0.5 m where the guess was 6.2 m off.
  const OdometryStep& step = r.steps[31 - first];
  EXPECT_FALSE(step.recovery.empty()) << "the guess's registration was not believed";
  const Eigen::Isometry3d truth = relative(*dataset->ground_truth(31), *dataset->ground_truth(32));
  EXPECT_LT(translation_norm(relative(truth, step.relative)), 0.5);
}

// The local map is right or says so too: after the untrusted step 31→32 its scan is placed by a
// doubtful motion, so the map starts again from it; before, steps 33→37 registered against a map
// holding that misplaced scan, fitted it, and said trusted while 3–22 m off. The local map is the
// default.
TEST(RealSequence, MulranLocalMapIsRightOrSaysSo) {
  if (!std::filesystem::is_directory(kMulran)) GTEST_SKIP() << "no " << kMulran;
  const auto dataset = open_dataset(kMulran);
  OdometrySettings s;
  s.guess = OdometryGuess::constant_velocity;
  ASSERT_EQ(s.map, OdometryMap::local_map);
  const std::size_t first = 26, count = 15;
  const OdometryResult r = run_odometry(*dataset, s, first, count);
  ASSERT_EQ(r.steps.size(), count - 1);
  const std::size_t trusted = trusted_steps_expecting_them_right(*dataset, r, first);
  EXPECT_GE(trusted, count / 2) << "most steps of a drive are registered and believed";
  // Keyframes 33→34 (13.7 m along a straight road): no registration is trusted and their fits lie
  // within 1.38–1.46 × of each other. The lowest fit is a wide-basin pose 21 m off, running
  // backwards; within the band of about-equal fits the one nearest the constant-velocity guess is
  // chained (suspect_choice.hpp), 1.4 m off, and the step says so.
  const OdometryStep& step = r.steps[33 - first];
  EXPECT_FALSE(step.trusted());
  EXPECT_EQ(step.recovery, "least_suspect");
  const Eigen::Isometry3d truth = relative(*dataset->ground_truth(33), *dataset->ground_truth(34));
  EXPECT_LT(translation_norm(relative(truth, step.relative)), 2.0);
}

// Every other keyframe of 4–26 (the car at 4–11 m per step), no times: the guess is the last
// motion. On 24→26 the first registration passes its own checks and the sequence check flags it; the
// wide basin then finds a second trusted pose 11 m away, sliding along the road. Both cannot be right
// (StepWorker::recover): the step is chained as the least suspect and says so. Before, the wide
// basin's pose was taken as trusted, 11 m off, and over the whole stretch read every other keyframe
// 16 trusted steps 5–24 m off followed it.
TEST(RealSequence, MulranEveryOtherKeyframeIsRightOrSaysSo) {
  if (!std::filesystem::is_directory(kMulran)) GTEST_SKIP() << "no " << kMulran;
  const auto full = open_dataset(kMulran);
  test::TempDir tmp;
  std::filesystem::create_directories(tmp / "scans");
  std::ifstream all_poses(kMulran / "poses.txt");
  std::vector<std::string> lines;
  for (std::string line; std::getline(all_poses, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 166u);
  std::string poses;
  std::size_t n = 0;
  for (std::size_t i = 4; i <= 26; i += 2, ++n) {
    const std::string name = std::string(6 - std::to_string(n).size(), '0') + std::to_string(n) + ".pcd";
    const std::string source = std::string(6 - std::to_string(i).size(), '0') + std::to_string(i) + ".pcd";
    std::filesystem::create_symlink(kMulran / "scans" / source, tmp / "scans" / name);
    poses += lines[i] + "\n";
  }
  test::write_text(tmp / "poses.txt", poses);
  const auto dataset = open_dataset(tmp.path());
  ASSERT_EQ(dataset->size(), n);
  ASSERT_FALSE(dataset->stamp(0).has_value());
  OdometrySettings s;
  s.guess = OdometryGuess::constant_velocity;  // the CLI's default for a dataset without odometry
  const OdometryResult r = run_odometry(*dataset, s, 0, n);
  ASSERT_EQ(r.steps.size(), n - 1);
  const std::size_t trusted = trusted_steps_expecting_them_right(*dataset, r, 0);
  EXPECT_GE(trusted, n / 2) << "most steps of a drive are registered and believed";
  const OdometryStep& last = r.steps.back();
  EXPECT_FALSE(last.trusted());
  EXPECT_EQ(last.recovery, "least_suspect");
  EXPECT_NE(last.quality.reason.find("ambiguous"), std::string::npos) << last.quality.reason;
  const Eigen::Isometry3d truth = relative(*dataset->ground_truth(n - 2), *dataset->ground_truth(n - 1));
  EXPECT_LT(translation_norm(relative(truth, last.relative)), 0.5) << "the prior chose the right one";
}

// A good guess stays good: from the reference pose, the default ML-NDT ends within the reference's
// own accuracy on MulRan pairs at walking pace and at speed (issue 22, "ML-NDT keeps a good guess"):
// refine_first runs the last layer from the guess and the precision stage refines it (measured
// 0.5–5.4 cm; from start layer 2 the coarse layers pulled 30→31 20.6 cm away, and the old outdoor
// preset 1.5–7 m). The bound is the reference's accuracy: point-to-plane ICP moves its pairs by
// 2–7 cm (../shared/data/README.md).
TEST(RealSequence, MulranPairsFromTheReferenceStayThere) {
  if (!std::filesystem::is_directory(kMulran)) GTEST_SKIP() << "no " << kMulran;
  const auto dataset = open_dataset(kMulran);
  for (const std::size_t i : {1u, 30u, 120u, 150u}) {
    const Eigen::Isometry3d truth = relative(*dataset->ground_truth(i), *dataset->ground_truth(i + 1));
    MlndtMatcher matcher;
    const auto gbs = make_sampler("gbs");
    Rng rng(1);
    const PairMatch m = match_pair(matcher, *gbs, dataset->scan(i), dataset->scan(i + 1), truth, rng);
    const Eigen::Isometry3d error = relative(truth, m.result.T);
    EXPECT_LT(translation_norm(error), 0.07) << "pair " << i << "→" << i + 1 << ": " << m.result.summary();
  }
}

}  // namespace
}  // namespace sextant
