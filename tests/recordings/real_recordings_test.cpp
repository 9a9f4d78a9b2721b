// The real recordings of ../shared/data/recordings read as its README says they are: the Ouster OS1-64
// MCAP (ROS 1 encoding, zstd chunks), the SICK LMS1xx bag (bz2 chunks), rosbag.js's ROS 1 fixtures
// (uncompressed, bz2, lz4, unsorted chunks, no messages). Skipped when the shared data are absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "container.hpp"
#include "point_cloud2.hpp"
#include "sextant/core/error.hpp"
#include "sextant/recordings/recording.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;
using namespace recordings_detail;

const fs::path kRecordings = fs::path(SEXTANT_SHARED_DATA_DIR) / "recordings";

#define REQUIRE_SHARED(path) \
  if (!fs::exists(path)) GTEST_SKIP() << path << " is absent (../shared/data beside the checkout)"

const TopicSummary& topic(const RecordingSummary& s, const std::string& name) {
  const auto it =
      std::find_if(s.topics.begin(), s.topics.end(), [&](const TopicSummary& t) { return t.name == name; });
  if (it == s.topics.end()) throw std::runtime_error("no topic " + name);
  return *it;
}

TEST(RealRecordings, TheOusterMcapHoldsTwoOrganisedScansWithPerPointTime) {
  const fs::path file = kRecordings / "ouster_os1_mcap" / "os1_ros1.mcap";
  REQUIRE_SHARED(file);
  const RecordingSummary s = describe_recording(file);
  EXPECT_EQ(s.format, "mcap");
  EXPECT_NE(s.storage.find("profile ros1, 2 zstd chunks, summary and chunk index"), std::string::npos)
      << s.storage;
  EXPECT_EQ(topic(s, "/os1_cloud_node/points").messages, 2u);
  EXPECT_EQ(topic(s, "/os1_cloud_node/imu").type, "sensor_msgs/Imu");
  EXPECT_EQ(topic(s, "/os1_cloud_node/imu").messages, 17u);
  EXPECT_EQ(topic(s, "/os1_node/lidar_packets").messages, 206u);
  EXPECT_EQ(topic(s, "/tf_static").messages, 1u);
  EXPECT_EQ(topic(s, "/rosout").messages, 12u);  // two channels, one topic
  const TopicSummary& points = topic(s, "/os1_cloud_node/points");
  EXPECT_EQ(points.type, "sensor_msgs/PointCloud2");
  EXPECT_EQ(points.encoding, "ros1");
  EXPECT_EQ(points.height, 64u);
  EXPECT_EQ(points.width, 2048u);
  EXPECT_EQ(points.point_step, 48u);
  const std::map<std::string, std::pair<std::string, std::uint32_t>> expected{
      {"x", {"float32", 0}},          {"y", {"float32", 4}},     {"z", {"float32", 8}},
      {"intensity", {"float32", 16}}, {"t", {"uint32", 20}},     {"reflectivity", {"uint16", 24}},
      {"ring", {"uint8", 26}},        {"noise", {"uint16", 28}}, {"range", {"uint32", 32}}};
  ASSERT_EQ(points.fields.size(), expected.size());
  for (const PointFieldSummary& f : points.fields) {
    ASSERT_TRUE(expected.count(f.name)) << f.name;
    EXPECT_EQ(f.datatype, expected.at(f.name).first) << f.name;
    EXPECT_EQ(f.offset, expected.at(f.name).second) << f.name;
  }

  const std::unique_ptr<Dataset> d = open_recording(file);
  ASSERT_EQ(d->size(), 2u);
  EXPECT_NEAR(*d->stamp(1) - *d->stamp(0), 0.1, 0.01);  // 10 Hz
  for (std::size_t i = 0; i < 2; ++i) {
    ScanLoadReport report;
    const PointCloud cloud = d->scan(i, &report);
    EXPECT_EQ(report.points_read, 64u * 2048u);
    EXPECT_EQ(report.non_finite_dropped, 0u);
    EXPECT_EQ(cloud.size() + report.no_return_dropped, 64u * 2048u);  // the rest are empty cells at (0, 0, 0)
    EXPECT_GT(cloud.size(), 40000u);
    ASSERT_TRUE(cloud.has_time());
    ASSERT_TRUE(cloud.has_intensity());
    const auto [lo, hi] = std::minmax_element(cloud.time().begin(), cloud.time().end());
    EXPECT_GE(*lo, 0.0f);
    EXPECT_NEAR(*hi - *lo, 0.1f, 0.01f);  // one sweep at 10 Hz, ns from the scan's start
    for (const Eigen::Vector3f& p : cloud.points()) ASSERT_LT(p.norm(), 120.0f);  // the OS1-64's range
  }
}

TEST(RealRecordings, TheOusterPointsLieAtTheRangeTheSensorMeasured) {
  const fs::path file = kRecordings / "ouster_os1_mcap" / "os1_ros1.mcap";
  REQUIRE_SHARED(file);
  auto container = open_container(file, 0);
  const std::vector<MessagePosition> scans = container->take_kept_messages();
  ASSERT_EQ(scans.size(), 2u);
  ChunkCache cache;
  const Bytes payload = container->read_message(scans[0], cache);
  const Place place{file.string(), 0, "", ""};
  const PointCloud2Message m = parse_point_cloud2(payload, MessageEncoding::ros1, place);
  // x, y, z against the driver's own `range` field (u32 mm at 32): the geometry is decoded right.
  std::vector<double> differences;
  for (std::size_t k = 0; k < std::size_t{m.height} * m.width; ++k) {
    const std::uint8_t* p = payload.data() + m.data_offset + k * m.point_step;
    float xyz[3];
    std::memcpy(xyz, p, sizeof xyz);
    const std::uint32_t range_mm = load_u32(p + 32);
    if (range_mm == 0) continue;
    differences.push_back(std::abs(Eigen::Vector3f(xyz[0], xyz[1], xyz[2]).norm() - 1e-3 * range_mm));
  }
  ASSERT_GT(differences.size(), 40000u);
  std::nth_element(differences.begin(), differences.begin() + differences.size() / 2, differences.end());
  EXPECT_LT(differences[differences.size() / 2], 0.05);  // the lidar's origin is a few cm from the sensor's
}

TEST(RealRecordings, TheSickBagHolds89ScansOf541Points) {
  const fs::path file = kRecordings / "sick_lms1xx_bag" / "rms_1xxx_lms_1xx_movement_off.bag";
  REQUIRE_SHARED(file);
  const RecordingSummary s = describe_recording(file);
  EXPECT_EQ(s.format, "rosbag1");
  EXPECT_NE(s.storage.find("bz2"), std::string::npos);
  EXPECT_EQ(topic(s, "/cloud").messages, 89u);
  EXPECT_EQ(topic(s, "/sick_lms_1xx/scan").type, "sensor_msgs/LaserScan");
  EXPECT_EQ(topic(s, "/sick_lms_1xx/scan").messages, 89u);
  try {  // radar clouds beside the lidar's: the topic must be chosen
    open_recording(file);
    ADD_FAILURE() << "three PointCloud2 topics opened without a topic";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/cloud (89 messages)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--topic"), std::string::npos) << e.what();
  }
  RecordingSelection chosen;
  chosen.topic = "/cloud";
  const std::unique_ptr<Dataset> d = open_recording(file, chosen);
  ASSERT_EQ(d->size(), 89u);
  for (std::size_t i = 0; i < d->size(); ++i) {
    ScanLoadReport report;
    const PointCloud cloud = d->scan(i, &report);
    EXPECT_EQ(report.points_read, 541u) << i;
    EXPECT_EQ(cloud.size() + report.dropped(), 541u) << i;
    EXPECT_TRUE(cloud.has_intensity());
    EXPECT_FALSE(cloud.has_time());  // the README: no per-point time
    if (i > 0) {
      EXPECT_GT(*d->stamp(i), *d->stamp(i - 1));
    }
  }
}

std::map<std::string, std::uint64_t> counts(const RecordingSummary& s) {
  std::map<std::string, std::uint64_t> c;
  for (const TopicSummary& t : s.topics) c[t.name + " " + t.type] = t.messages;
  return c;
}

TEST(RealRecordings, TheTurtlesimBagReadsAlikeUncompressedBz2AndLz4) {
  const fs::path folder = kRecordings / "rosbag1_fixtures";
  REQUIRE_SHARED(folder);
  const RecordingSummary plain = describe_recording(folder / "example.bag");
  EXPECT_EQ(plain.messages, 8647u);
  EXPECT_EQ(counts(plain).at("/turtle1/pose turtlesim/Pose"), 1344u);
  EXPECT_EQ(counts(plain).at("/tf tf/tfMessage"), 2688u);
  EXPECT_EQ(counts(plain).at("/rosout rosgraph_msgs/Log"), 10u);  // three connections
  for (const char* name : {"example-bz2.bag", "example-lz4.bag"}) {
    const RecordingSummary s = describe_recording(folder / name);
    EXPECT_EQ(counts(s), counts(plain)) << name;
    EXPECT_EQ(s.start, plain.start) << name;
    EXPECT_EQ(s.end, plain.end) << name;
  }
  // The messages themselves, decompressed (ROS's lz4 chunks are LZ4 frames), equal the uncompressed ones.
  const auto poses = [&](const char* name) {
    auto c = open_container(folder / name, 0, false,
                            [](const Connection& k) { return k.topic == "/turtle1/pose"; });
    std::vector<MessagePosition> p = c->take_kept_messages();
    std::sort(p.begin(), p.end(), [](auto& a, auto& b) { return a.log_time < b.log_time; });
    ChunkCache cache;
    std::vector<Bytes> data;
    for (std::size_t k = 0; k < p.size(); k += 97) data.push_back(c->read_message(p[k], cache));
    EXPECT_EQ(p.size(), 1344u) << name;
    return data;
  };
  const std::vector<Bytes> expected = poses("example.bag");
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(expected.front().size(), 20u);  // turtlesim/Pose: five float32
  EXPECT_EQ(poses("example-bz2.bag"), expected);
  EXPECT_EQ(poses("example-lz4.bag"), expected);
}

TEST(RealRecordings, UnsortedChunksAndAnEmptyBag) {
  const fs::path folder = kRecordings / "rosbag1_fixtures";
  REQUIRE_SHARED(folder);
  const RecordingSummary unsorted = describe_recording(folder / "example-unsorted-chunks.bag");
  ASSERT_EQ(unsorted.topics.size(), 1u);
  EXPECT_EQ(unsorted.topics[0].name, "foo");
  EXPECT_EQ(unsorted.topics[0].type, "std_msgs/String");
  EXPECT_EQ(unsorted.topics[0].messages, 3u);
  auto c = open_container(folder / "example-unsorted-chunks.bag", 0, false,
                          [](const Connection&) { return true; });
  const std::vector<MessagePosition> found = c->take_kept_messages();  // in the order of the chunks
  ASSERT_EQ(found.size(), 3u);
  EXPECT_FALSE(
      std::is_sorted(found.begin(), found.end(), [](auto& a, auto& b) { return a.log_time < b.log_time; }));

  const RecordingSummary empty = describe_recording(folder / "no-messages.bag");
  EXPECT_EQ(empty.messages, 0u);
  EXPECT_TRUE(empty.topics.empty());
  EXPECT_FALSE(empty.start.has_value());
  try {
    open_recording(folder / "no-messages.bag");
    ADD_FAILURE() << "a bag without messages gave scans";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no sensor_msgs/PointCloud2 topic"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sextant
