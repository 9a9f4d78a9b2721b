#pragma once
// Private: which files a recording is made of. A .bag or .mcap file is itself; a ROS 2 bag folder is
// the files its metadata.yaml lists (relative_file_paths: a split bag is several), or, in the old
// layout without metadata.yaml, its .db3 files in the order of the number in their names.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sextant::recordings_detail {

struct RecordingFiles {
  std::filesystem::path path;  ///< as the user named it
  std::string format;          ///< "rosbag1", "rosbag2" or "mcap"
  std::vector<std::filesystem::path> files;
  bool zstd_messages = false;  ///< rosbag2's per-message zstd compression
  std::string layout;          ///< "metadata.yaml", "old layout without metadata.yaml", or empty for a file
};

/// The files of the recording at `path`, or nullopt when it is not one (a folder of scans, a cloud
/// file). InputError for a rosbag2 metadata.yaml it cannot follow (a listed file missing, a whole-file
/// compression).
std::optional<RecordingFiles> find_recording_files(const std::filesystem::path& path);

/// What metadata.yaml says of its files (only rosbag2's block layout of these keys is read: the topics
/// and counts come from the files themselves).
struct Rosbag2Metadata {
  std::string storage_identifier;  ///< "sqlite3", "mcap"
  std::vector<std::string> relative_file_paths;
  std::string compression_format, compression_mode;
};
/// Nullopt when it is not rosbag2's metadata (no rosbag2_bagfile_information map).
std::optional<Rosbag2Metadata> read_rosbag2_metadata(const std::filesystem::path& file);

}  // namespace sextant::recordings_detail
