// rosbag2's own test bags (../shared/data/recordings/rosbag2_fixtures) read as their metadata.yaml files
// say: sqlite3 and MCAP storage, a split bag, the old layout without metadata.yaml, topics and services.
// Skipped when the shared data are absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "container.hpp"
#include "sextant/core/error.hpp"
#include "sextant/recordings/recording.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;
using namespace recordings_detail;

const fs::path kBags = fs::path(SEXTANT_SHARED_DATA_DIR) / "recordings" / "rosbag2_fixtures";

#define REQUIRE_SHARED(path) \
  if (!fs::exists(path)) GTEST_SKIP() << path << " is absent (../shared/data beside the checkout)"

std::map<std::string, std::uint64_t> counts(const fs::path& bag) {
  std::map<std::string, std::uint64_t> c;
  for (const TopicSummary& t : describe_recording(bag).topics) c[t.name + " " + t.type] = t.messages;
  return c;
}

TEST(RealRosbag2, TheTalkerBagReadsAlikeFromSqliteAndMcap) {
  const fs::path sqlite = kBags / "rosbag2_py_test_resources_sqlite3_talker";
  const fs::path mcap = kBags / "rosbag2_py_test_resources_mcap_talker";
  REQUIRE_SHARED(sqlite);
  const std::map<std::string, std::uint64_t> expected{
      {"/topic std_msgs/msg/String", 10},
      {"/rosout rcl_interfaces/msg/Log", 10},
      {"/parameter_events rcl_interfaces/msg/ParameterEvent", 0}};
  EXPECT_EQ(counts(sqlite), expected);
  EXPECT_EQ(counts(mcap), expected);
  EXPECT_EQ(describe_recording(sqlite).format, "rosbag2");
  EXPECT_NE(describe_recording(mcap).storage.find("zstd"), std::string::npos);
  // The strings the talker published, in CDR (header 00 01 00 00, u32 length with the NUL, the text).
  const auto strings = [](const fs::path& file) {
    auto c = open_container(file, 0, false, [](const Connection& k) { return k.topic == "/topic"; });
    std::vector<MessagePosition> p = c->take_kept_messages();
    std::sort(p.begin(), p.end(), [](auto& a, auto& b) { return a.log_time < b.log_time; });
    ChunkCache cache;
    std::vector<std::string> out;
    for (const MessagePosition& m : p) {
      const Bytes data = c->read_message(m, cache);
      EXPECT_EQ(data[1], 1) << "little-endian CDR";
      out.emplace_back(data.begin() + 8, data.end() - 1);
    }
    return out;
  };
  const std::vector<std::string> a = strings(sqlite / "talker.db3"), b = strings(mcap / "talker.mcap");
  ASSERT_EQ(a.size(), 10u);
  EXPECT_EQ(a.front(), "Hello, world! 0");
  EXPECT_EQ(a.back(), "Hello, world! 9");
  EXPECT_EQ(a, b);
}

TEST(RealRosbag2, ASplitMcapBagCountsEveryFile) {
  const fs::path bag = kBags / "rosbag2_py_test_resources_mcap_wbag";
  REQUIRE_SHARED(bag);
  const RecordingSummary s = describe_recording(bag);
  EXPECT_EQ(s.files.size(), 5u);
  EXPECT_EQ(s.messages, 6074u);  // metadata.yaml's message_count
  const std::map<std::string, std::uint64_t> expected{
      {"AAA std_msgs/msg/String", 804}, {"BBB std_msgs/msg/String", 742}, {"CCC std_msgs/msg/String", 742},
      {"DDD std_msgs/msg/String", 753}, {"EEE std_msgs/msg/String", 804}, {"FFF std_msgs/msg/String", 772},
      {"GGG std_msgs/msg/String", 731}, {"HHH std_msgs/msg/String", 726}};
  EXPECT_EQ(counts(bag), expected);  // the channel ids differ from file to file; the topics do not
}

TEST(RealRosbag2, TheOldLayoutIsItsDb3FilesInOrder) {
  const fs::path bag = kBags / "rosbag2_py_test_resources_sqlite3_reindex_test_bags_multiple_files";
  REQUIRE_SHARED(bag);
  EXPECT_TRUE(is_recording(bag));
  const RecordingSummary s = describe_recording(bag);
  ASSERT_EQ(s.files.size(), 3u);
  EXPECT_EQ(s.files[0].filename(), "multiple_files_0.db3");
  EXPECT_EQ(s.files[2].filename(), "multiple_files_2.db3");
  EXPECT_EQ(counts(bag),
            (std::map<std::string, std::uint64_t>{{"/chatter std_msgs/msg/String", 1324 + 1324 + 529}}));
  EXPECT_NE(s.storage.find("old layout without metadata.yaml"), std::string::npos) << s.storage;
}

TEST(RealRosbag2, CdrTestBagsAndServiceEvents) {
  const fs::path cdr_sqlite = kBags / "rosbag2_tests_resources_sqlite3_cdr_test";
  REQUIRE_SHARED(cdr_sqlite);
  const std::map<std::string, std::uint64_t> cdr{{"/test_topic test_msgs/msg/BasicTypes", 3},
                                                 {"/array_topic test_msgs/msg/Arrays", 4}};
  EXPECT_EQ(counts(cdr_sqlite), cdr);
  EXPECT_EQ(counts(kBags / "rosbag2_tests_resources_mcap_cdr_test"), cdr);
  const fs::path both = kBags / "rosbag2_cpp_test_rosbag2_cpp_bags";
  for (const char* file : {"topics_and_services.db3", "topics_and_services.mcap"}) {
    const std::map<std::string, std::uint64_t> c = counts(both / file);
    EXPECT_EQ(c.at("/add_two_ints/_service_event example_interfaces/srv/AddTwoInts_Event"), 6u) << file;
    EXPECT_EQ(c.at("/parameter_events rcl_interfaces/msg/ParameterEvent"), 7u) << file;
    EXPECT_EQ(c.size(), 5u) << file;
  }
  EXPECT_EQ(counts(both / "only_services.mcap")
                .at("/add_two_ints/_service_event example_interfaces/srv/AddTwoInts_Event"),
            12u);
  EXPECT_EQ(describe_recording(both / "only_topics.mcap").messages, 7u);
  try {  // no lidar in any of them: the error lists what there is
    open_recording(cdr_sqlite);
    ADD_FAILURE() << "a bag without point clouds gave scans";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/array_topic (test_msgs/msg/Arrays, 4 messages)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sextant
