#pragma once
// Robot recordings as datasets, read without a ROS installation: ROS 1 bags (v2.0; uncompressed, bz2
// and lz4 chunks; indexed or not), MCAP files (profiles ros1 and ros2; uncompressed, zstd and lz4
// chunks; with or without a summary) and ROS 2 bags (a folder with metadata.yaml, its sqlite3 .db3 or
// MCAP files, split bags included; the old .db3 layout without metadata.yaml). One scan per
// sensor_msgs/PointCloud2 message of one topic, in log-time order (docs/formats.md, "Recordings").
//
//   RecordingSelection chosen;  chosen.topic = "/points";  chosen.every = 2;
//   std::unique_ptr<Dataset> scans = open_dataset_or_recording("drive.bag", chosen);
//   PointCloud first = scans->scan(0);  // xyz, intensity, per-point time from the scan's stamp
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sextant/core/dataset.hpp"

namespace sextant {

/// Which messages of a recording are its scans.
struct RecordingSelection {
  /// The sensor_msgs/PointCloud2 topic; empty: the recording's only one.
  std::string topic;
  double start = 0.0;              ///< [s] from the recording's first message (any topic)
  std::optional<double> duration;  ///< [s] from `start`; none: to the end
  std::size_t every = 1;           ///< every N-th message of the topic in the part chosen (≥ 1)
  /// How the caller spells the topic argument in messages ("--topic" on the command line, "topic=" in
  /// Python), for the error that asks for one.
  std::string topic_argument = "--topic";

  /// True when nothing but the defaults is chosen (a folder of scans takes no selection).
  bool is_default() const;
  /// The first field whose value cannot be honoured ("start": finite and ≥ 0, "duration": finite and
  /// > 0, "every": ≥ 1) and why, or two empty strings.
  std::pair<std::string, std::string> problem() const;
  /// problem() as the settings structs say it: false and "field: why".
  bool valid(std::string* why) const;
};

/// A point field of a sensor_msgs/PointCloud2 message.
struct PointFieldSummary {
  std::string name;
  std::string datatype;  ///< int8 uint8 int16 uint16 int32 uint32 float32 float64
  std::uint32_t offset = 0;
  std::uint32_t count = 1;
};

/// What one topic holds: its messages over all the connections (ROS 1) or channels (MCAP) that carry it.
struct TopicSummary {
  std::string name;
  std::string type;      ///< as recorded: "sensor_msgs/PointCloud2" (ROS 1) or "sensor_msgs/msg/PointCloud2"
  std::string encoding;  ///< "ros1" or "cdr" (or what the file names, when neither)
  std::uint64_t messages = 0;
  bool point_cloud = false;  ///< a sensor_msgs/PointCloud2 topic
  /// Of the first message, for a point-cloud topic with messages.
  std::vector<PointFieldSummary> fields;
  std::uint32_t height = 0, width = 0, point_step = 0;
  std::string frame_id;
};

struct RecordingSummary {
  std::filesystem::path path;
  std::string format;   ///< "rosbag1", "rosbag2" or "mcap"
  std::string storage;  ///< how it is stored, e.g. "bz2 chunks, indexed", "sqlite3, 3 files"
  std::vector<std::filesystem::path> files;
  std::uint64_t messages = 0;
  /// Log times of the first and last message [s] (since the epoch, for a recording of a robot's clock).
  std::optional<double> start, end;
  std::vector<TopicSummary> topics;  ///< sorted by name
};

/// A ROS 1 bag, an MCAP file, a rosbag2 .db3 file, or a folder with a rosbag2 metadata.yaml or .db3
/// files (by extension and, for a file with another name, by its first bytes).
bool is_recording(const std::filesystem::path& path);

/// The topics, types, message counts, time span and point fields of a recording. InputError naming the
/// file and the byte offset (or record) of anything malformed; FileError for a file it cannot open.
RecordingSummary describe_recording(const std::filesystem::path& path);

/// The scans of one PointCloud2 topic: stamp(i) is the message's header stamp [s since the epoch],
/// scan(i) its points in the message's frame (NaN/Inf points dropped as non-finite, (0, 0, 0) as
/// no-return, each counted), with per-point time when a field holds one (point_time.hpp), scan_file(i)
/// the file holding the message; no odometry or ground truth. InputError, naming the topics with their
/// message counts, when `selection.topic` is empty and the recording has no or several PointCloud2
/// topics, or names a topic that is not one; InputError when the selection holds no message.
std::unique_ptr<Dataset> open_recording(const std::filesystem::path& path,
                                        const RecordingSelection& selection = {});

/// A recording (is_recording) through open_recording, else a dataset folder through core's open_dataset;
/// InputError when a selection is given for a folder that is not a recording.
std::unique_ptr<Dataset> open_dataset_or_recording(const std::filesystem::path& path,
                                                   const RecordingSelection& selection = {});

}  // namespace sextant
