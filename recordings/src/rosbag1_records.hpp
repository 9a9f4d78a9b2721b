#pragma once
// Private: the records of a ROS 1 bag, format v2.0 (wiki.ros.org/Bags/Format/2.0): each is
// <header length u32><header: fields "name=value", each with a u32 length><data length u32><data>,
// its kind the header's `op` byte. Little-endian; a time is u32 seconds then u32 nanoseconds.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "byte_cursor.hpp"
#include "file_reader.hpp"

namespace sextant::recordings_detail {

namespace rosbag1_op {
inline constexpr std::uint8_t kMessage = 0x02, kBagHeader = 0x03, kIndex = 0x04, kChunk = 0x05,
                              kChunkInfo = 0x06, kConnection = 0x07;
}

/// A record's header fields, names to raw values, and where it lies.
struct Rosbag1Record {
  std::vector<std::pair<std::string, std::string>> fields;
  std::uint8_t op = 0;
  std::uint64_t offset = 0;       ///< of its first byte, in the file or the chunk
  std::uint64_t data_offset = 0;  ///< of its data
  std::uint32_t data_size = 0;
  std::uint64_t end() const { return data_offset + data_size; }
  std::string where;  ///< "byte N" (or "byte N of the bz2 chunk at byte M"), for messages

  /// The field `name` as a u32, u64 or time [ns]; InputError naming the record when it is missing or
  /// of another size.
  std::uint32_t u32(const std::string& file, const char* name) const;
  std::uint64_t u64(const std::string& file, const char* name) const;
  std::int64_t time_ns(const std::string& file, const char* name) const;
  const std::string& text(const std::string& file, const char* name) const;
  bool has(const char* name) const;
};

/// The header fields of a record's header bytes (`cursor` at its first field, `size` bytes of them).
std::vector<std::pair<std::string, std::string>> parse_rosbag1_fields(ByteCursor& cursor, std::size_t size);

/// The record at `offset` of the file (header read, data not), or of the bytes under `cursor` (its
/// position at the record; left at the record's end).
Rosbag1Record read_rosbag1_record(const FileReader& file, std::uint64_t offset);
Rosbag1Record read_rosbag1_record(ByteCursor& cursor);

/// A connection record's topic and its data's `type` (the data is itself a list of fields).
struct Rosbag1Connection {
  std::uint32_t id = 0;
  std::string topic, type;
};
Rosbag1Connection parse_rosbag1_connection(const Rosbag1Record& record, const Bytes& data,
                                           const Place& place);

/// "#ROSBAG V2.0\n": the first 13 bytes of a bag.
inline constexpr char kRosbag1Magic[] = "#ROSBAG V2.0\n";
inline constexpr std::size_t kRosbag1MagicSize = 13;

}  // namespace sextant::recordings_detail
