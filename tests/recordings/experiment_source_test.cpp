// An experiment config's `source: folder` takes a recording as its path, with `topic:`, `start:`,
// `duration:` and `every:` checked like the other keys (line and key named) and used as the CLI does.
#include <gtest/gtest.h>

#include <string>

#include "bag_writer.hpp"
#include "kit/dataset_source.hpp"
#include "known_scans.hpp"
#include "sextant/core/error.hpp"
#include "sextant/experiments/experiment_config.hpp"
#include "sextant_test/temp_dir.hpp"

namespace sextant {
namespace {

ExperimentConfig config_with(const std::string& dataset, const test::TempDir& tmp) {
  const std::string text = "name: x\nkind: registration\ndataset:\n" + dataset + "methods: [{name: a}]\n";
  return parse_experiment_config(YAML::Load(text), (tmp / "e99_x.yaml").string(), false);
}

std::string problem_of(const std::string& dataset, const test::TempDir& tmp) {
  try {
    const ExperimentConfig c = config_with(dataset, tmp);
    open_experiment_dataset(c, "registration");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << dataset;
  return "";
}

TEST(ExperimentSource, ARecordingWithItsSelection) {
  const test::TempDir tmp;
  std::vector<test::TestMessage> messages = test::known_messages(30, true);
  messages.push_back(test::known_message(0, true, "/other"));
  test::write_bag(tmp / "drive.bag", messages, test::bag_options("bz2", 10, true, false));
  const ExperimentConfig c = config_with(
      "  source: folder\n  path: drive.bag\n  topic: /points\n  start: 1\n  duration: 1\n  every: 3\n", tmp);
  EXPECT_EQ(c.dataset.recording.topic, "/points");
  EXPECT_EQ(c.dataset.recording.every, 3u);
  ASSERT_TRUE(c.dataset.recording.duration.has_value());
  check_experiment_dataset(c, "registration");
  const std::unique_ptr<Dataset> d = open_experiment_dataset(c, "registration");  // the path is relative
  ASSERT_EQ(d->size(), 4u);
  test::expect_known_scan(d->scan(1), 13);
  EXPECT_EQ(d->metadata().format, "rosbag1");
}

TEST(ExperimentSource, BadKeysAreNamed) {
  const test::TempDir tmp;
  std::vector<test::TestMessage> messages = test::known_messages(3, true);
  messages.push_back(test::known_message(0, true, "/other"));
  test::write_bag(tmp / "drive.bag", messages, {});
  const std::string every = problem_of("  source: folder\n  path: drive.bag\n  every: 0\n", tmp);
  EXPECT_NE(every.find("line 6"), std::string::npos) << every;
  EXPECT_NE(every.find("key 'every': expected a whole number ≥ 1"), std::string::npos) << every;
  EXPECT_NE(problem_of("  source: folder\n  path: drive.bag\n  duration: -2\n", tmp).find("key 'duration'"),
            std::string::npos);
  EXPECT_NE(problem_of("  source: synthetic\n  topic: /points\n", tmp)
                .find("key 'topic' is only used with source: folder (a recording)"),
            std::string::npos);
  EXPECT_NE(problem_of("  source: folder\n  path: drive.bag\n  topc: /points\n", tmp).find("topc"),
            std::string::npos);
  const std::string several = problem_of("  source: folder\n  path: drive.bag\n", tmp);
  EXPECT_NE(
      several.find("2 sensor_msgs/PointCloud2 topics: /other (1 message), /points (3 messages); choose one "
                   "with the key 'topic' of "),
      std::string::npos)
      << several;
  test::write_text(tmp / "scans" / "000001.xyz", "1 2 3\n");
  EXPECT_NE(problem_of("  source: folder\n  path: scans\n  every: 2\n", tmp).find("is not a recording"),
            std::string::npos);
}

}  // namespace
}  // namespace sextant
