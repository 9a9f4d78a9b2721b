// `sextant odometry`, `info` and `match --index` on recordings, end to end: the first scans of the
// synthetic campus copied into a bag run as the campus itself does, the part chosen by --start,
// --duration and --every is the one run and provenance.json records it, and bad choices are named.
#include <gtest/gtest.h>

#include <string>

#include "bag_writer.hpp"
#include "cloud_writer.hpp"
#include "mcap_writer.hpp"
#include "sextant/core/io/trajectory_io.hpp"
#include "sextant/synth/campus.hpp"
#include "sextant/synth/settings.hpp"
#include "sextant_test/cli_run.hpp"
#include "sextant_test/temp_dir.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;

test::CliRun run(const std::string& arguments) {
  return test::run_cli(SEXTANT_CLI, arguments);
}

constexpr std::size_t kScans = 8;
constexpr double kFirstStamp = 1700000000.0;

/// The campus' first scans (seed 1, as `sextant odometry campus`) as PointCloud2 messages 0.1 s apart.
std::vector<test::TestMessage> campus_messages(bool ros1) {
  const synth::CampusDataset campus(synth::generate_campus(synth::CampusSettings{}, 1));
  std::vector<test::TestMessage> messages;
  for (std::size_t k = 0; k < kScans; ++k) {
    const PointCloud scan = campus.scan(k);
    std::vector<std::vector<double>> values;
    for (std::size_t i = 0; i < scan.size(); ++i) values.push_back({scan[i].x(), scan[i].y(), scan[i].z()});
    test::TestCloud c = test::make_test_cloud({{"x", 7}, {"y", 7}, {"z", 7}}, values);
    c.sec = static_cast<std::int32_t>(kFirstStamp) + static_cast<std::int32_t>(k / 10);
    c.nsec = static_cast<std::uint32_t>(k % 10) * 100000000u;
    const std::int64_t t = static_cast<std::int64_t>(c.sec) * 1000000000 + c.nsec;
    messages.push_back({"/points", ros1 ? "sensor_msgs/PointCloud2" : "sensor_msgs/msg/PointCloud2", t,
                        ros1 ? test::serialize_ros1(c) : test::serialize_cdr(c)});
  }
  return messages;
}

TEST(RecordingCli, TheCampusCopiedIntoABagRunsAsTheCampus) {
  const test::TempDir tmp;
  test::write_bag(tmp / "campus.bag", campus_messages(true), test::bag_options("lz4", 3, true, false));
  const std::string same = " --guess constant_velocity --max-acceleration 0 --no-progress --out ";
  const test::CliRun campus =
      run("odometry campus --scans " + std::to_string(kScans) + same + (tmp / "a").string());
  ASSERT_EQ(campus.exit_code, 0) << campus.output;
  const test::CliRun bag = run("odometry " + (tmp / "campus.bag").string() + same + (tmp / "b").string());
  ASSERT_EQ(bag.exit_code, 0) << bag.output;
  EXPECT_NE(bag.output.find("(rosbag1, 8 scans; odometry no, ground truth no)"), std::string::npos)
      << bag.output;
  EXPECT_NE(bag.output.find("note:     topic /points (sensor_msgs/PointCloud2, ros1): 8 of its 8 messages"),
            std::string::npos)
      << bag.output;
  const Trajectory a = read_tum_trajectory(tmp / "a" / "trajectory.tum");
  const Trajectory b = read_tum_trajectory(tmp / "b" / "trajectory.tum");
  ASSERT_EQ(a.size(), kScans);
  ASSERT_EQ(b.size(), kScans);
  for (std::size_t k = 0; k < kScans; ++k) {
    // The same clouds, the same steps (the campus' trajectory starts at its ground truth, the bag's at the
    // identity).
    const Eigen::Isometry3d campus_motion = a[0].pose.inverse() * a[k].pose;
    EXPECT_TRUE(b[k].pose.isApprox(campus_motion, 1e-6)) << "scan " << k;
    EXPECT_NEAR(b[k].stamp, kFirstStamp + 0.1 * static_cast<double>(k), 1e-6);  // the header stamps
  }
  const std::string provenance = test::read_text(tmp / "b" / "provenance.json");
  EXPECT_NE(provenance.find("\"format\": \"rosbag1\""), std::string::npos) << provenance;
  EXPECT_NE(provenance.find("\"topic\": \"\", \"start\": 0.0, \"duration\": null, \"every\": 1"),
            std::string::npos)
      << provenance;
}

TEST(RecordingCli, StartDurationAndEveryChooseTheScansRun) {
  const test::TempDir tmp;
  test::write_mcap(tmp / "campus.mcap", campus_messages(false), {});
  const test::CliRun r = run("odometry " + (tmp / "campus.mcap").string() +
                             " --topic /points --start 0.2 --duration 0.5 --every 2 --no-progress --out " +
                             (tmp / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("3 of its 8 messages, from 0.2 s for 0.5 s, every 2nd message"), std::string::npos)
      << r.output;
  const Trajectory t = read_tum_trajectory(tmp / "out" / "trajectory.tum");
  ASSERT_EQ(t.size(), 3u);  // scans 2, 4, 6
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_NEAR(t[i].stamp, kFirstStamp + 0.2 * static_cast<double>(i + 1), 1e-6);
  const std::string provenance = test::read_text(tmp / "out" / "provenance.json");
  EXPECT_NE(provenance.find("\"topic\": \"/points\", \"start\": 0.2, \"duration\": 0.5, \"every\": 2"),
            std::string::npos)
      << provenance;

  const test::CliRun info = run("info " + (tmp / "campus.mcap").string());
  EXPECT_EQ(info.exit_code, 0) << info.output;
  EXPECT_NE(info.output.find("format:       mcap (profile ros2"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("fields: x float32 @0, y float32 @4, z float32 @8"), std::string::npos)
      << info.output;
  const test::CliRun match = run("match " + (tmp / "campus.mcap").string() + " --index 3 4 --json");
  EXPECT_EQ(match.exit_code, 0) << match.output;
  EXPECT_NE(match.output.find("\"trust\": \"ok\""), std::string::npos) << match.output;
}

TEST(RecordingCli, BadChoicesAreNamed) {
  const test::TempDir tmp;
  test::write_mcap(tmp / "campus.mcap", campus_messages(false), {});
  const std::string rec = (tmp / "campus.mcap").string(), out = " --out " + (tmp / "never").string();
  const test::CliRun every = run("odometry " + rec + " --every 0" + out);
  EXPECT_EQ(every.exit_code, 2) << every.output;
  EXPECT_NE(every.output.find("--every"), std::string::npos) << every.output;
  const test::CliRun duration = run("odometry " + rec + " --duration -1" + out);
  EXPECT_EQ(duration.exit_code, 2) << duration.output;
  const test::CliRun late = run("odometry " + rec + " --start 5" + out);
  EXPECT_EQ(late.exit_code, 1) << late.output;
  EXPECT_NE(late.output.find("holds none of the 8 messages of /points"), std::string::npos) << late.output;
  const test::CliRun folder =
      run("odometry " + std::string(SEXTANT_DATA_DIR) + "/uos_3dtk --topic /points" + out);
  EXPECT_EQ(folder.exit_code, 1) << folder.output;
  EXPECT_NE(folder.output.find("sextant: error: --topic: only for a recording"), std::string::npos)
      << folder.output;
  const test::CliRun campus = run("odometry campus --every 2" + out);
  EXPECT_NE(campus.output.find("--every: only for a recording, not the campus"), std::string::npos)
      << campus.output;
  const test::CliRun both = run("match " + rec + " " + rec + " --index 0 1");
  EXPECT_EQ(both.exit_code, 2) << both.output;
  EXPECT_FALSE(fs::exists(tmp / "never"));
}

}  // namespace
}  // namespace sextant
