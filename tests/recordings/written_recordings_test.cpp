// Recordings written with known content in every format and compression read back exactly: the scans'
// points, intensities, per-point times and stamps, in log-time order, and the topics' counts.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "bag_writer.hpp"
#include "known_scans.hpp"
#include "mcap_writer.hpp"
#include "rosbag2_writer.hpp"
#include "sextant/recordings/recording.hpp"
#include "sextant_test/temp_dir.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;
using test::TestMessage;

struct WrittenCase {
  std::string name;     ///< the test's name
  std::string format;   ///< what the dataset says it is
  bool ros1 = false;    ///< the messages' serialization
  std::string path;     ///< file or folder name
  std::string storage;  ///< in the summary's storage: which way it was read
  std::function<void(const fs::path&, const std::vector<TestMessage>&)> write;
};

void PrintTo(const WrittenCase& c, std::ostream* os) {
  *os << c.name;
}

std::vector<WrittenCase> written_cases() {
  using namespace test;
  const auto bag = [](BagOptions o) {
    return [o](const fs::path& p, const std::vector<TestMessage>& m) { write_bag(p, m, o); };
  };
  const auto mcap = [](McapOptions o) {
    return [o](const fs::path& p, const std::vector<TestMessage>& m) { write_mcap(p, m, o); };
  };
  const auto bag2 = [](Rosbag2Options o) {
    return [o](const fs::path& p, const std::vector<TestMessage>& m) { write_rosbag2(p, m, o); };
  };
  BagOptions bz2, lz4, unindexed, reversed;
  bz2.compression = "bz2";
  lz4.compression = "lz4";
  unindexed.compression = "bz2";
  unindexed.index = false;
  reversed.compression = "lz4";
  reversed.reverse_chunks = true;
  McapOptions zstd, mcap_lz4, ros1_profile, unchunked, no_summary, no_footer;
  zstd.compression = "zstd";
  mcap_lz4.compression = "lz4";
  ros1_profile.profile = "ros1";
  ros1_profile.compression = "zstd";
  unchunked.chunked = false;
  no_summary.summary = false;
  no_summary.compression = "lz4";
  no_footer.footer = false;
  no_footer.compression = "zstd";
  Rosbag2Options split, old_layout, per_message, mcap_split;
  split.files = 3;
  old_layout.files = 3;
  old_layout.metadata = false;
  per_message.zstd_messages = true;
  mcap_split.storage = "mcap";
  mcap_split.files = 2;
  return {
      {"BagUncompressed", "rosbag1", true, "a.bag", "3 uncompressed chunks, indexed", bag({})},
      {"BagBz2", "rosbag1", true, "a.bag", "3 bz2 chunks, indexed", bag(bz2)},
      {"BagLz4", "rosbag1", true, "a.bag", "3 lz4 chunks, indexed", bag(lz4)},
      {"BagWithoutIndex", "rosbag1", true, "a.bag", "no index: read in one pass", bag(unindexed)},
      {"BagWithChunksOutOfOrder", "rosbag1", true, "a.bag", "lz4 chunks, indexed", bag(reversed)},
      {"McapUncompressed", "mcap", false, "a.mcap", "uncompressed chunks, summary and chunk index", mcap({})},
      {"McapZstd", "mcap", false, "a.mcap", "zstd chunks, summary and chunk index", mcap(zstd)},
      {"McapLz4", "mcap", false, "a.mcap", "lz4 chunks, summary", mcap(mcap_lz4)},
      {"McapRos1Profile", "mcap", true, "a.mcap", "profile ros1, 3 zstd chunks", mcap(ros1_profile)},
      {"McapUnchunked", "mcap", false, "a.mcap", "no chunks, read in one pass", mcap(unchunked)},
      {"McapWithoutSummary", "mcap", false, "a.mcap", "no index: read in one pass", mcap(no_summary)},
      {"McapCutShort", "mcap", false, "a.mcap", "no index: read in one pass", mcap(no_footer)},
      {"Rosbag2Sqlite", "rosbag2", false, "bag", "sqlite3 (metadata.yaml)", bag2({})},
      {"Rosbag2SqliteSplit", "rosbag2", false, "bag", "3 files, the first: sqlite3", bag2(split)},
      {"Rosbag2OldLayout", "rosbag2", false, "bag", "(old layout without metadata.yaml)", bag2(old_layout)},
      {"Rosbag2ZstdPerMessage", "rosbag2", false, "bag", "sqlite3, zstd per message", bag2(per_message)},
      {"Rosbag2McapSplit", "rosbag2", false, "bag", "2 files, the first: profile ros2", bag2(mcap_split)},
  };
}

class Written : public ::testing::TestWithParam<WrittenCase> {};

TEST_P(Written, ScansReadBackExactlyInTimeOrder) {
  const WrittenCase& c = GetParam();
  const test::TempDir tmp;
  const fs::path path = tmp / c.path;
  constexpr std::size_t kScans = 25;
  c.write(path, test::known_messages(kScans, c.ros1));
  ASSERT_TRUE(is_recording(path));
  const std::unique_ptr<Dataset> d = open_dataset_or_recording(path);
  EXPECT_EQ(d->metadata().format, c.format);
  ASSERT_EQ(d->size(), kScans);
  EXPECT_FALSE(d->metadata().has_odometry);
  EXPECT_FALSE(d->metadata().has_ground_truth);
  for (std::size_t k = 0; k < kScans; ++k) {
    ScanLoadReport report;
    const PointCloud cloud = d->scan(k, &report);
    test::expect_known_scan(cloud, k);
    EXPECT_EQ(report.points_read, 5u);
    EXPECT_EQ(report.no_return_dropped, k == 0 ? 1u : 0u);
    EXPECT_EQ(report.non_finite_dropped, 0u);
    ASSERT_TRUE(d->stamp(k).has_value());
    EXPECT_NEAR(*d->stamp(k), 1.7e9 + 0.1 * static_cast<double>(k), 1e-6) << k;
    EXPECT_FALSE(d->odometry(k).has_value());
    EXPECT_FALSE(d->scan_file(k).empty());
  }
}

TEST_P(Written, DescribeCountsEveryTopicAndNamesThePointFields) {
  const WrittenCase& c = GetParam();
  const test::TempDir tmp;
  const fs::path path = tmp / c.path;
  c.write(path, test::known_messages(12, c.ros1));
  const RecordingSummary s = describe_recording(path);
  EXPECT_EQ(s.format, c.format);
  EXPECT_EQ(s.messages, 24u);
  EXPECT_NE(s.storage.find(c.storage), std::string::npos) << s.storage;
  ASSERT_EQ(s.topics.size(), 2u);
  EXPECT_EQ(s.topics[0].name, "/chatter");
  EXPECT_FALSE(s.topics[0].point_cloud);
  EXPECT_EQ(s.topics[0].messages, 12u);
  const TopicSummary& points = s.topics[1];
  EXPECT_EQ(points.name, "/points");
  EXPECT_TRUE(points.point_cloud);
  EXPECT_EQ(points.messages, 12u);
  EXPECT_EQ(points.encoding, c.ros1 ? "ros1" : "cdr");
  EXPECT_EQ(points.width, 5u);
  EXPECT_EQ(points.height, 1u);
  EXPECT_EQ(points.point_step, 20u);
  EXPECT_EQ(points.frame_id, "lidar");
  ASSERT_EQ(points.fields.size(), 5u);
  EXPECT_EQ(points.fields[4].name, "t");
  EXPECT_EQ(points.fields[4].datatype, "uint32");
  EXPECT_EQ(points.fields[4].offset, 16u);
  ASSERT_TRUE(s.start && s.end);
  EXPECT_NEAR(*s.start, 1.7e9, 1e-5);
  EXPECT_NEAR(*s.end - *s.start, 1.1 + 0.05, 1e-5);  // the last /chatter message, 50 ms after scan 11
}

INSTANTIATE_TEST_SUITE_P(EveryFormat, Written, ::testing::ValuesIn(written_cases()),
                         [](const ::testing::TestParamInfo<WrittenCase>& info) { return info.param.name; });

}  // namespace
}  // namespace sextant
