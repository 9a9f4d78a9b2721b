// Which messages of a recording are its scans: the topic (the only PointCloud2 one, or the one named),
// the part from --start for --duration, every N-th; and the errors that list the topics to choose from.
#include <gtest/gtest.h>

#include <string>

#include "bag_writer.hpp"
#include "known_scans.hpp"
#include "mcap_writer.hpp"
#include "sextant/core/error.hpp"
#include "sextant/recordings/recording.hpp"
#include "sextant_test/temp_dir.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;

std::string problem_of(const fs::path& path, const RecordingSelection& s) {
  try {
    open_dataset_or_recording(path, s);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "opened";
  return "";
}

TEST(RecordingSelection, StartDurationAndEveryChooseByLogTime) {
  const test::TempDir tmp;
  test::write_bag(tmp / "a.bag", test::known_messages(30, true), test::bag_options("bz2", 7, true, false));
  RecordingSelection s;
  s.start = 1.0;  // from the first message: scans 10 … 19 lie in [1, 2) s
  s.duration = 1.0;
  s.every = 3;
  const std::unique_ptr<Dataset> d = open_recording(tmp / "a.bag", s);
  ASSERT_EQ(d->size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const std::size_t k = 10 + 3 * i;
    test::expect_known_scan(d->scan(i), k);
    EXPECT_NEAR(*d->stamp(i), 1.7e9 + 0.1 * static_cast<double>(k), 1e-6);
  }
  EXPECT_NE(d->metadata().notes.front().find("4 of its 30 messages, from 1 s for 1 s, every 3rd message"),
            std::string::npos)
      << d->metadata().notes.front();
  RecordingSelection rest;
  rest.start = 2.55;  // scans 26 … 29
  EXPECT_EQ(open_recording(tmp / "a.bag", rest)->size(), 4u);
  RecordingSelection every;
  every.every = 7;  // 0, 7, 14, 21, 28
  EXPECT_EQ(open_recording(tmp / "a.bag", every)->size(), 5u);
}

TEST(RecordingSelection, ThePointCloudTopicsAreListedWhenOneMustBeChosen) {
  const test::TempDir tmp;
  std::vector<test::TestMessage> messages = test::known_messages(6, false, "/front/points");
  for (std::size_t k = 0; k < 4; ++k) messages.push_back(test::known_message(k, false, "/rear/points"));
  test::write_mcap(tmp / "two.mcap", messages, {});
  const std::string several = problem_of(tmp / "two.mcap", {});
  EXPECT_EQ(several.rfind((tmp / "two.mcap").string(), 0), 0u) << several;
  EXPECT_NE(
      several.find("2 sensor_msgs/PointCloud2 topics: /front/points (6 messages), /rear/points (4 messages); "
                   "choose one with --topic"),
      std::string::npos)
      << several;
  RecordingSelection python;
  python.topic_argument = "topic=";
  EXPECT_NE(problem_of(tmp / "two.mcap", python).find("choose one with topic="), std::string::npos);
  RecordingSelection rear;
  rear.topic = "/rear/points";
  const std::unique_ptr<Dataset> d = open_recording(tmp / "two.mcap", rear);
  ASSERT_EQ(d->size(), 4u);
  test::expect_known_scan(d->scan(3), 3);
  RecordingSelection missing;
  missing.topic = "/top/points";
  EXPECT_NE(problem_of(tmp / "two.mcap", missing)
                .find("no topic '/top/points' (its sensor_msgs/PointCloud2 topics: "
                      "/front/points (6 messages), /rear/points (4 messages))"),
            std::string::npos);
  RecordingSelection chatter;
  chatter.topic = "/chatter";
  EXPECT_NE(problem_of(tmp / "two.mcap", chatter)
                .find("topic '/chatter' holds std_msgs/msg/String, not "
                      "sensor_msgs/PointCloud2"),
            std::string::npos);
}

TEST(RecordingSelection, NothingChosenOrAnImpossibleChoiceIsAnError) {
  const test::TempDir tmp;
  test::write_bag(tmp / "a.bag", test::known_messages(5, true), {});
  RecordingSelection late;
  late.start = 10.0;
  EXPECT_NE(problem_of(tmp / "a.bag", late)
                .find("the selection (from 10 s to the end) holds none of the 5 messages of "
                      "/points (the recording spans 0.449999 s)"),
            std::string::npos)
      << problem_of(tmp / "a.bag", late);
  RecordingSelection negative;
  negative.start = -1.0;
  EXPECT_NE(problem_of(tmp / "a.bag", negative).find("start: expected a finite number of seconds ≥ 0"),
            std::string::npos);
  RecordingSelection zero;
  zero.duration = 0.0;
  EXPECT_NE(problem_of(tmp / "a.bag", zero).find("duration: expected a finite number of seconds > 0"),
            std::string::npos);
  RecordingSelection never;
  never.every = 0;
  EXPECT_NE(problem_of(tmp / "a.bag", never).find("every: expected a whole number ≥ 1"), std::string::npos);
  EXPECT_EQ(never.problem().first, "every");
  EXPECT_TRUE(RecordingSelection{}.valid(nullptr));
  // A folder of scans takes no selection.
  test::write_text(tmp / "scans" / "000001.xyz", "1 2 3\n4 5 6\n");
  RecordingSelection topic;
  topic.topic = "/points";
  EXPECT_NE(problem_of(tmp / "scans", topic).find("is not a recording"), std::string::npos);
  EXPECT_EQ(open_dataset_or_recording(tmp / "scans")->size(), 1u);
  EXPECT_FALSE(is_recording(tmp / "scans"));
}

}  // namespace
}  // namespace sextant
