#pragma once
// Private: one file of a recording as the formats' readers open it: its connections (ROS 1
// connections, MCAP channels, rosbag2 topics), their message counts, its time span, and where the
// messages of its point-cloud connections lie, so that any one of them is read again later without
// reading the others (a position of 24 bytes per message; nothing of the messages themselves is kept).
// Positions are kept for the messages of the connections a KeepMessages says (the point clouds).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "byte_cursor.hpp"
#include "chunk_cache.hpp"

namespace sextant::recordings_detail {

/// How a connection's messages are serialized.
enum class MessageEncoding { ros1, cdr, other };

struct Connection {
  std::string topic;
  std::string type;           ///< "sensor_msgs/PointCloud2" or "sensor_msgs/msg/PointCloud2", …
  std::string encoding_name;  ///< "ros1", "cdr", or what the file names
  MessageEncoding encoding = MessageEncoding::other;
  std::uint64_t messages = 0;
};

/// sensor_msgs/PointCloud2 in either spelling (ROS 1 "sensor_msgs/PointCloud2", ROS 2 ".../msg/...").
bool is_point_cloud2_type(const std::string& type);

/// Which connections' messages a container keeps the positions of.
using KeepMessages = std::function<bool(const Connection&)>;
/// The default: sensor_msgs/PointCloud2 connections.
bool keeps_point_clouds(const Connection& c);

inline constexpr std::uint32_t kNoChunk = std::numeric_limits<std::uint32_t>::max();

/// Where one message lies: 24 bytes.
struct MessagePosition {
  std::int64_t log_time = 0;  ///< [ns]
  /// In the chunk's uncompressed records (a chunked message), else in the file (kNoChunk), or the row
  /// id of a rosbag2 sqlite3 message.
  std::uint64_t offset = 0;
  std::uint32_t chunk = kNoChunk;
  std::uint16_t file = 0;        ///< which file of a split recording
  std::uint16_t connection = 0;  ///< index in the file's connections()
};
static_assert(sizeof(MessagePosition) == 24, "a message's position takes 24 bytes");

class Container {
 public:
  virtual ~Container() = default;

  const std::string& file() const { return file_; }
  /// "rosbag1", "rosbag2" or "mcap".
  const std::string& format() const { return format_; }
  /// How the messages are stored: "bz2 chunks, indexed", "sqlite3", "zstd chunks, linear pass", …
  const std::string& storage() const { return storage_; }
  const std::vector<Connection>& connections() const { return connections_; }
  /// The log times of the first and last message [ns], when it has messages.
  std::optional<std::int64_t> first_time() const { return first_time_; }
  std::optional<std::int64_t> last_time() const { return last_time_; }
  /// The positions of the messages of the connections it keeps (KeepMessages), in the order found (the
  /// caller sorts them by time); taken once.
  std::vector<MessagePosition> take_kept_messages() { return std::move(kept_); }

  /// The payload of the message at `position` (its first `prefix` bytes at most): the serialized
  /// message, for a rosbag2 bag compressed per message decompressed. Decompressed chunks come from and
  /// go to `cache`.
  virtual Bytes read_message(const MessagePosition& position, ChunkCache& cache,
                             std::size_t prefix = std::numeric_limits<std::size_t>::max()) const = 0;
  /// Where the message lies, for messages about it: "the message at byte 120 of the bz2 chunk at byte 4117".
  virtual std::string describe(const MessagePosition& position) const = 0;

 protected:
  /// Records a message's time in the span.
  void saw_time(std::int64_t t) {
    if (!first_time_ || t < *first_time_) first_time_ = t;
    if (!last_time_ || t > *last_time_) last_time_ = t;
  }

  Container(std::uint16_t file_index, KeepMessages keep) : file_index_(file_index), keep_(std::move(keep)) {}
  bool keeps(std::uint16_t connection) const { return keep_(connections_[connection]); }
  /// Counts a message of `connection` found at `offset` (of `chunk`), records its time, and keeps its
  /// position when the connection is kept.
  void add_message(std::uint16_t connection, std::int64_t time, std::uint32_t chunk, std::uint64_t offset) {
    ++connections_[connection].messages;
    saw_time(time);
    if (keeps(connection)) kept_.push_back(MessagePosition{time, offset, chunk, file_index_, connection});
  }

  std::uint16_t file_index_;  ///< which file of a split recording, stored in every position

  KeepMessages keep_;
  std::string file_, format_, storage_;
  std::vector<Connection> connections_;
  std::optional<std::int64_t> first_time_, last_time_;
  std::vector<MessagePosition> kept_;
};

/// Opens one file, its format by its first bytes (ROS 1 bag, MCAP, sqlite3; `zstd_messages`: a rosbag2
/// sqlite3 file compressed per message); `file_index` is stored
/// in every position. InputError naming the file when it is none of them.
std::unique_ptr<Container> open_container(const std::filesystem::path& file, std::uint16_t file_index,
                                          bool zstd_messages = false, KeepMessages keep = keeps_point_clouds);

/// What the first bytes of a file say it is: "rosbag1", "mcap", "sqlite3", or empty.
std::string sniff_format(const std::filesystem::path& file);

std::unique_ptr<Container> open_rosbag1(const std::filesystem::path& file, std::uint16_t file_index,
                                        KeepMessages keep);
std::unique_ptr<Container> open_mcap(const std::filesystem::path& file, std::uint16_t file_index,
                                     KeepMessages keep);
std::unique_ptr<Container> open_rosbag2_sqlite(const std::filesystem::path& file, std::uint16_t file_index,
                                               bool zstd_messages, KeepMessages keep);

}  // namespace sextant::recordings_detail
