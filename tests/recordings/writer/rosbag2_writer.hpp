#pragma once
// Test-only: ROS 2 bag folders as rosbag2 writes them: metadata.yaml (rosbag2_bagfile_information,
// its block layout) and one or more storage files, sqlite3 (the `topics` and `messages` tables, through
// libsqlite3) or MCAP (mcap_writer.hpp), the messages split evenly over the files.
#include <filesystem>
#include <string>
#include <vector>

#include "recording_message.hpp"

namespace sextant::test {

struct Rosbag2Options {
  std::string storage = "sqlite3";  ///< sqlite3 or mcap
  std::size_t files = 1;
  bool metadata = true;        ///< false: the old layout, .db3 files alone
  bool zstd_messages = false;  ///< compression_format zstd, compression_mode message
  std::string
      compression_mode;  ///< written as given when not empty (e.g. "file", to test that it is refused)
};

/// Writes `messages` (CDR data) into the folder `folder` (created), named after it: <name>_0.db3, ….
void write_rosbag2(const std::filesystem::path& folder, const std::vector<TestMessage>& messages,
                   const Rosbag2Options& options = {});

}  // namespace sextant::test
