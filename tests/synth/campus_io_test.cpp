// Writing the campus: byte-identical output for a seed, the uos round trip through core's
// Dataset, the cache folder and the preview.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "sextant/core/io/uos.hpp"
#include "sextant/synth/campus_io.hpp"
#include "sextant_test/temp_dir.hpp"
#include "small_campus.hpp"

namespace sextant::synth {
namespace {

namespace fs = std::filesystem;

using sextant::test::read_text;
using sextant::test::TempDir;

std::map<std::string, std::string> folder_contents(const fs::path& root) {
  std::map<std::string, std::string> out;
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.is_regular_file()) out[fs::relative(entry.path(), root).string()] = read_text(entry.path());
  return out;
}

TEST(CampusIo, SameSeedGivesByteIdenticalFiles) {
  TempDir tmp;
  const Campus c = generate_campus(test::small_campus(5), 21);
  write_campus(c, tmp.path() / "a");
  write_campus(generate_campus(test::small_campus(5), 21), tmp.path() / "b");
  const auto a = folder_contents(tmp.path() / "a");
  const auto b = folder_contents(tmp.path() / "b");
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [name, bytes] : a) EXPECT_TRUE(b.count(name) && b.at(name) == bytes) << name;
  for (const char* expected :
       {"scan000.3d", "scan004.pose", "scan004.frames", "landmarks.txt", "visibility.txt", "ground_truth.tum",
        "odometry.tum", "campus.yaml", "preview.svg", "oxts/data/0000000004.txt", "oxts/timestamps.txt",
        "oxts/dataformat.txt"})
    EXPECT_TRUE(a.count(expected)) << expected;
  // Different seed → different bytes.
  write_campus(generate_campus(test::small_campus(5), 22), tmp.path() / "c");
  EXPECT_NE(read_text(tmp.path() / "a" / "scan000.3d"), read_text(tmp.path() / "c" / "scan000.3d"));
}

TEST(CampusIo, UosRoundTripReproducesCloudsAndPoses) {
  TempDir tmp;
  const Campus c = generate_campus(test::small_campus(4), 23);
  write_campus(c, tmp.path());
  const auto ds = open_dataset(tmp.path());
  ASSERT_EQ(ds->size(), c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    const SimulatedScan s = c.scan(i);
    const PointCloud back = ds->scan(i);
    ASSERT_EQ(back.size(), s.cloud.size());
    for (std::size_t k = 0; k < back.size(); ++k)
      ASSERT_LE((back[k] - s.cloud[k]).norm(), 1e-4) << i << ":" << k;
    ASSERT_TRUE(ds->ground_truth(i));
    ASSERT_TRUE(ds->odometry(i));
    EXPECT_LE((ds->ground_truth(i)->matrix() - c.ground_truth[i].matrix()).cwiseAbs().maxCoeff(), 1e-4);
    EXPECT_LE((ds->odometry(i)->matrix() - c.odometry[i].matrix()).cwiseAbs().maxCoeff(), 1e-4);
  }
}

TEST(CampusIo, VisibilityFileListsThePointsPerLandmark) {
  TempDir tmp;
  const Campus c = generate_campus(test::small_campus(3), 24);
  write_campus(c, tmp.path());
  std::ifstream in(tmp.path() / "visibility.txt");
  std::string line;
  std::map<std::pair<int, int>, std::size_t> rows;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    int scan = 0, id = 0;
    std::size_t points = 0;
    ls >> scan >> id >> points;
    rows[{scan, id}] = points;
  }
  std::size_t expected = 0;
  for (std::size_t i = 0; i < c.size(); ++i)
    for (const auto& v : c.scan(i).visible) {
      ++expected;
      EXPECT_EQ((rows[{static_cast<int>(i), v.landmark}]), v.points);
    }
  EXPECT_EQ(rows.size(), expected);
}

TEST(CampusIo, EnsureCampusGeneratesOnceAndReuses) {
  TempDir tmp;
  const CampusSettings s = test::small_campus(2);
  const fs::path first = ensure_campus(s, 5, tmp.path());
  ASSERT_TRUE(fs::exists(first / "campus.yaml"));
  const auto stamp = fs::last_write_time(first / "scan000.3d");
  const fs::path second = ensure_campus(s, 5, tmp.path());
  EXPECT_EQ(first, second);
  EXPECT_EQ(stamp, fs::last_write_time(second / "scan000.3d"));
  EXPECT_NE(ensure_campus(s, 6, tmp.path()), first);
  std::size_t leftovers = 0;
  for (const auto& e : fs::directory_iterator(tmp.path()))
    leftovers += e.path().filename().string()[0] == '.';
  EXPECT_EQ(leftovers, 0u);
}

}  // namespace
}  // namespace sextant::synth
